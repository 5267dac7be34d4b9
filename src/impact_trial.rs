//! One head-on impact run by tamp and compared with its closed form: the experiment
//! behind the core's error model (`tamp study accuracy-calibration`, which runs
//! `calibration_trials`) and its check (the case `accuracy_on_demand`). The bodies
//! feel nothing but their contact (no gravity), so the probe's largest force is the
//! contact's. It builds its impacts as scenes, so it lives here, beside the cases and
//! studies, rather than in the core's `accuracy`, which the scene builder uses.

use crate::accuracy::calibration::{
    DAMPED_RESTITUTION_MIN, DENSITY, RADIUS, STIFFNESS, STORAKERS_SPEED_RATIOS,
    THORNTON_SPEED_RATIOS, THORNTON_YIELD_PRESSURE, WALTON_BRAUN_RATIOS,
};
use crate::accuracy::damped_hertz::{Dashpot, c_for_restitution};
use crate::accuracy::impact::{Impact, closed_form};
use crate::collision::{binary_collision, plane_collision};
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::normal::NormalLaw;
use crate::contact::normal::linear::LinearCollision;
use crate::contact::normal::thornton::yield_velocity;
use crate::error::{Result, TampError};
use crate::material::PairProperties;
use crate::material::{effective_mass, effective_radius};
use crate::particles::Vec3;
use crate::scene;
use serde_json::{Value, json};

/// What hits what.
#[derive(Clone, Copy, Debug)]
pub enum Partner {
    /// A second sphere of this radius, at rest, of the scene's last material.
    Sphere(f64),
    /// A fixed plane z = 0 of the scene's last material.
    Wall,
}

/// One impact: sphere of `radius` (first material) at `speed` towards the partner.
#[derive(Clone, Debug)]
pub struct Trial {
    pub name: &'static str,
    /// `materials` and `contact` of the scene, as the scene file writes them.
    pub materials: Value,
    pub contact: Value,
    pub radius: f64,
    pub partner: Partner,
    pub speed: f64,
}

/// What one run measured, next to the closed form.
#[derive(Clone, Copy, Debug)]
pub struct Outcome {
    pub measured: Impact,
    pub exact: Impact,
    /// The step the run used, s.
    pub dt: f64,
}

impl Outcome {
    /// The step over the error model's time scale (`Impact::time_scale`).
    pub fn step_ratio(&self) -> f64 {
        self.dt / self.exact.time_scale
    }
}

impl Trial {
    /// The scene of this impact with `time_step` as given; the moving sphere starts
    /// `gap` (m) from its partner.
    pub fn scene(&self, time_step: Value, gap: f64) -> Value {
        let last = self.materials.as_array().map_or(1, |m| m.len()) - 1;
        let name = |k: usize| self.materials[k]["name"].clone();
        let (partner, walls) = match self.partner {
            Partner::Sphere(r) => (
                vec![json!({"position": [0, 0, 0], "radius": r, "material": name(last)})],
                json!([]),
            ),
            Partner::Wall => (
                vec![],
                json!([{"name": "wall", "material": name(last),
                         "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}]),
            ),
        };
        let offset = match self.partner {
            Partner::Sphere(r) => r,
            Partner::Wall => 0.0,
        };
        let mut particles = vec![json!({
            "position": [0, 0, offset + self.radius + gap],
            "radius": self.radius,
            "material": name(0),
            "velocity": [0, 0, -self.speed],
        })];
        particles.extend(partner);
        json!({
            "name": self.name,
            "materials": self.materials,
            "contact": self.contact,
            "particles": particles,
            "walls": walls,
            "time_step": time_step,
            "run": {"steps": 1},
        })
    }

    /// The impact built as a simulation (a tiny step and gap: only its bodies, law
    /// and pair properties are read).
    fn built(&self) -> Result<crate::simulation::Simulation> {
        let s = scene::parse(
            &self
                .scene(json!({"fixed": 1e-15}), self.radius * 1e-3)
                .to_string(),
        )?;
        Ok(scene::build(&s)?.sim)
    }

    /// The closed form of this impact (the step does not enter it).
    pub fn exact(&self) -> Result<Impact> {
        self.closed_form(&self.built()?)
    }

    /// This impact at the approach speed v/v_y = `v_over_vy` times Thornton's yield
    /// velocity of its contact (the scene's law must be `thornton`).
    pub fn at_yield_ratio(mut self, v_over_vy: f64) -> Result<Trial> {
        let sim = self.built()?;
        let NormalLaw::Thornton(law) = sim.model().law.normal else {
            return Err(TampError::Other(format!(
                "{}: not a thornton law",
                self.name
            )));
        };
        let (m, r, pair) = self.effective(&sim);
        let c = law.at(r, &pair);
        self.speed = v_over_vy * yield_velocity(c.yield_pressure, c.effective_modulus, r, m);
        Ok(self)
    }

    /// This impact at the approach speed v/v* = `ratio` times the speed at which its
    /// Storåkers loading leaves Hertz's curve (the scene's law must be `storakers`).
    pub fn at_hertz_crossing_ratio(mut self, ratio: f64) -> Result<Trial> {
        let sim = self.built()?;
        let NormalLaw::Storakers(law) = sim.model().law.normal else {
            return Err(TampError::Other(format!(
                "{}: not a storakers law",
                self.name
            )));
        };
        let (m, r, pair) = self.effective(&sim);
        let v_star = law.at(r, &pair).hertz_crossing_speed(m).ok_or_else(|| {
            TampError::Other(format!("{}: no Hertz crossing (m >= 1)", self.name))
        })?;
        self.speed = ratio * v_star;
        Ok(self)
    }

    /// Effective mass and radius of the impact, and its pair's properties.
    fn effective(&self, sim: &crate::simulation::Simulation) -> (f64, f64, PairProperties) {
        let p = &sim.state().particles;
        match self.partner {
            Partner::Sphere(_) => (
                effective_mass(p.mass[0], p.mass[1]),
                effective_radius(p.radius[0], p.radius[1]),
                *sim.model().pair_table.get(p.material[0], p.material[1]),
            ),
            Partner::Wall => (
                p.mass[0],
                p.radius[0],
                *sim.model()
                    .pair_table
                    .get(p.material[0], sim.model().walls[0].material),
            ),
        }
    }

    fn closed_form(&self, sim: &crate::simulation::Simulation) -> Result<Impact> {
        let (m, r, pair) = self.effective(sim);
        closed_form(&sim.model().law, m, r, &pair, self.speed).ok_or_else(|| {
            TampError::Other(format!("{}: the law has no impact closed form", self.name))
        })
    }

    /// Run the impact with `time_step` from a gap of `gap_steps` steps of travel (the
    /// fraction sets where in a step first touch falls).
    pub fn run(&self, time_step: Value, gap_steps: f64) -> Result<Outcome> {
        // The step is known only once the scene is built: build at a nominal gap, then
        // rebuild at the gap in steps of the step it chose.
        let nominal = scene::parse(
            &self
                .scene(time_step.clone(), self.radius * 1e-3)
                .to_string(),
        )?;
        let dt = scene::build(&nominal)?.sim.dt();
        let s = scene::parse(
            &self
                .scene(time_step, gap_steps * self.speed * dt)
                .to_string(),
        )?;
        let mut sim = scene::build(&s)?.sim;
        let exact = self.closed_form(&sim)?;
        let max_steps = (100.0 * exact.duration / sim.dt()) as u64 + gap_steps as u64 + 1000;
        let c = match self.partner {
            Partner::Sphere(_) => binary_collision(&mut sim, 0, 1, max_steps)?,
            Partner::Wall => plane_collision(&mut sim, 0, Vec3::zeros(), Vec3::z(), max_steps)?,
        };
        Ok(Outcome {
            measured: Impact {
                time_scale: exact.time_scale,
                duration: c.duration,
                max_overlap: c.max_overlap,
                max_force: c.max_force,
                restitution: c.restitution,
            },
            exact,
            dt: sim.dt(),
        })
    }
}

/// Each law's calibration impacts, by the law's name in `accuracy::calibration::MODELS`.
pub fn calibration_trials() -> Result<Vec<(&'static str, Trial)>> {
    let steel = json!([{"name": "steel", "density": DENSITY, "youngs_modulus": 2e11, "poisson_ratio": 0.3}]);
    let trial = |name, contact| Trial {
        name,
        materials: steel.clone(),
        contact,
        radius: RADIUS,
        partner: Partner::Sphere(RADIUS),
        speed: 1.0,
    };
    let m_eff = 0.5 * DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let damped = |name, e: f64| {
        let gamma_n = LinearCollision::gamma_for_restitution(STIFFNESS, m_eff, e);
        trial(
            name,
            json!({"normal": {"law": "linear", "stiffness": STIFFNESS},
                   "damping": {"kind": "constant", "gamma_n": gamma_n}}),
        )
    };
    let walton_braun = |name, ratio: f64| {
        trial(
            name,
            json!({"normal": {"law": "walton_braun", "loading_stiffness": STIFFNESS,
                              "unloading_stiffness": ratio * STIFFNESS}}),
        )
    };
    let hertz_damped = |name, e: f64| {
        trial(
            name,
            json!({"normal": {"law": "hertz"},
                   "damping": {"kind": "critical_fraction",
                               "xi": LiggghtsModel::Hertz.critical_fraction(e)}}),
        )
    };
    let thornton = |name, v_over_vy| {
        trial(
            name,
            json!({"normal": {"law": "thornton", "yield_pressure": THORNTON_YIELD_PRESSURE}}),
        )
        .at_yield_ratio(v_over_vy)
    };
    // The speed-dependent dashpots at the c whose unit impact rebounds at e, for the
    // calibration's pair at 1 m/s (δ_s = (m* v²/K)^{2/5}).
    let e_star = 2e11 / (2.0 * (1.0 - 0.3f64.powi(2)));
    let k_hertz = 4.0 / 3.0 * e_star * (0.5 * RADIUS).sqrt();
    let overlap_scale = (m_eff / k_hertz).powf(0.4);
    let kuwabara_kono = |name, e: f64| {
        let c = c_for_restitution(Dashpot::KuwabaraKono, e, 20.0);
        trial(
            name,
            json!({"normal": {"law": "kuwabara_kono",
                              "dissipation_time": c * overlap_scale / 1.5}}),
        )
    };
    let hertz_constant = |name, e: f64| {
        let c = c_for_restitution(Dashpot::Constant, e, 1.2);
        trial(
            name,
            json!({"normal": {"law": "hertz"},
                   "damping": {"kind": "constant", "gamma_n": c * m_eff / overlap_scale}}),
        )
    };
    // NiAl, Rojek Table 2 (clippy mistakes ν = 0.318 for 1/π).
    #[allow(clippy::approx_constant)]
    let nial = json!([{"name": "NiAl", "density": 5910.0, "youngs_modulus": 183e9,
                       "poisson_ratio": 0.318,
                       "hollomon": {"exponent": 0.2, "yield_stress": 800e6}}]);
    let storakers = |name, ratio| {
        Trial {
            name,
            materials: nial.clone(),
            contact: json!({"normal": {"law": "storakers", "min_with_hertz": true}}),
            radius: 1e-5,
            partner: Partner::Sphere(1e-5),
            speed: 1.0,
        }
        .at_hertz_crossing_ratio(ratio)
    };
    let [s0, s1, s2, s3] = STORAKERS_SPEED_RATIOS;
    let [r0, r1, r2, r3] = WALTON_BRAUN_RATIOS;
    let [t0, t1, t2, t3, t4] = THORNTON_SPEED_RATIOS;
    Ok(vec![
        (
            "linear",
            trial(
                "linear",
                json!({"normal": {"law": "linear", "stiffness": STIFFNESS}}),
            ),
        ),
        ("linear_damped", damped("linear, e = 0.9", 0.9)),
        ("linear_damped", damped("linear, e = 0.5", 0.5)),
        (
            "linear_damped",
            damped("linear, e = 0.1", DAMPED_RESTITUTION_MIN),
        ),
        ("hertz", trial("hertz", json!({"normal": {"law": "hertz"}}))),
        (
            "walton_braun",
            walton_braun("walton_braun, k2 = 1.25 k1", r0),
        ),
        ("walton_braun", walton_braun("walton_braun, k2 = 2 k1", r1)),
        ("walton_braun", walton_braun("walton_braun, k2 = 4 k1", r2)),
        ("walton_braun", walton_braun("walton_braun, k2 = 10 k1", r3)),
        ("hertz_damped", hertz_damped("hertz, xi for e = 0.9", 0.9)),
        ("hertz_damped", hertz_damped("hertz, xi for e = 0.5", 0.5)),
        (
            "hertz_damped",
            hertz_damped("hertz, xi for e = 0.1", DAMPED_RESTITUTION_MIN),
        ),
        ("thornton", thornton("thornton, v = 0.5 v_y", t0)?),
        ("thornton", thornton("thornton, v = 1.5 v_y", t1)?),
        ("thornton", thornton("thornton, v = 3 v_y", t2)?),
        ("thornton", thornton("thornton, v = 10 v_y", t3)?),
        ("thornton", thornton("thornton, v = 30 v_y", t4)?),
        (
            "kuwabara_kono",
            kuwabara_kono("kuwabara_kono, A for e = 0.9", 0.9),
        ),
        (
            "kuwabara_kono",
            kuwabara_kono("kuwabara_kono, A for e = 0.5", 0.5),
        ),
        (
            "kuwabara_kono",
            kuwabara_kono("kuwabara_kono, A for e = 0.1", DAMPED_RESTITUTION_MIN),
        ),
        (
            "hertz_constant_damped",
            hertz_constant("hertz, constant gamma_n for e = 0.9", 0.9),
        ),
        (
            "hertz_constant_damped",
            hertz_constant("hertz, constant gamma_n for e = 0.5", 0.5),
        ),
        (
            "hertz_constant_damped",
            hertz_constant(
                "hertz, constant gamma_n for e = 0.1",
                DAMPED_RESTITUTION_MIN,
            ),
        ),
        (
            "storakers_min_hertz",
            storakers("storakers min_with_hertz, NiAl, v = 0.5 v*", s0)?,
        ),
        (
            "storakers_min_hertz",
            storakers("storakers min_with_hertz, NiAl, v = 1.5 v*", s1)?,
        ),
        (
            "storakers_min_hertz",
            storakers("storakers min_with_hertz, NiAl, v = 3 v*", s2)?,
        ),
        (
            "storakers_min_hertz",
            storakers("storakers min_with_hertz, NiAl, v = 10 v*", s3)?,
        ),
    ])
}
