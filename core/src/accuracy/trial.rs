//! One head-on impact run by tamp and compared with its closed form: the experiment
//! behind the error model (`tamp study accuracy-calibration`) and its check (the
//! case `accuracy_on_demand`). The bodies feel nothing but their contact (no
//! gravity), so the probe's largest force is the contact's.

use super::impact::{Impact, closed_form};
use crate::contact::normal::NormalLaw;
use crate::contact::normal::thornton::yield_velocity;
use crate::error::{Result, TampError};
use crate::material::PairProperties;
use crate::material::{effective_mass, effective_radius};
use crate::measure::collision::{binary_collision, plane_collision};
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
        let NormalLaw::Thornton(law) = sim.law.normal else {
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
        let NormalLaw::Storakers(law) = sim.law.normal else {
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
        let p = &sim.particles;
        match self.partner {
            Partner::Sphere(_) => (
                effective_mass(p.mass[0], p.mass[1]),
                effective_radius(p.radius[0], p.radius[1]),
                *sim.pair_table.get(p.material[0], p.material[1]),
            ),
            Partner::Wall => (
                p.mass[0],
                p.radius[0],
                *sim.pair_table.get(p.material[0], sim.walls[0].material),
            ),
        }
    }

    fn closed_form(&self, sim: &crate::simulation::Simulation) -> Result<Impact> {
        let (m, r, pair) = self.effective(sim);
        closed_form(&sim.law, m, r, &pair, self.speed).ok_or_else(|| {
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
        let dt = scene::build(&nominal)?.sim.dt;
        let s = scene::parse(
            &self
                .scene(time_step, gap_steps * self.speed * dt)
                .to_string(),
        )?;
        let mut sim = scene::build(&s)?.sim;
        let exact = self.closed_form(&sim)?;
        let max_steps = (100.0 * exact.duration / sim.dt) as u64 + gap_steps as u64 + 1000;
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
            dt: sim.dt,
        })
    }
}
