//! `tamp study stable-alpha`: the largest safety factor α (Δt = α·Δt_cr, Rojek 2016
//! eq 26) at which each contact law stays stable in a dense, persistently loaded
//! packing, found by bisection.
//!
//! The scene is a face-centred cubic lattice of 108 equal spheres (3 × 3 × 3 cubic
//! cells, periodic on all three axes), every sphere pressed into its 12 neighbours
//! by the same small overlap δ₀ = 10⁻³ R, so every contact stays closed, and set
//! vibrating with small random velocities and spins (amplitude about 1 % of δ₀).
//! FCC rather than simple cubic because its central-force network is rigid: a
//! simple cubic lattice under compression buckles sideways when the law has no
//! tangential stiffness, a physical instability that would hide the numerical one.
//!
//! A run of 4000 steps is unstable when it stops with an instability diagnostic or
//! its mechanical energy (kinetic + stored, Simulation::mechanical_energy) rises
//! above its start by more than 10 initial kinetic energies: an elastic law
//! conserves it to O(Δt²), a dissipative one loses it, and an integration
//! instability gains it exponentially.
//!
//! Closed form for the linear law without friction: the lattice's highest
//! frequency is ω_max = √(λ k/m), λ the largest eigenvalue over the lattice's wave
//! vectors of Σ_r (1 − cos q·r) r̂r̂ᵀ (r over the 12 neighbour vectors); velocity
//! Verlet is stable for ω_max Δt < 2, and tamp's estimate takes k_i = Σ k = 12k, so
//! α_max = √(12/λ). Hertz linearised at δ₀ has the same limit.

use crate::contact::normal::NormalLaw;
use crate::contact::registry;
use crate::contact::tangential::TangentialLaw;
use crate::error::{Result, TampError};
use crate::scene;
use nalgebra::{Matrix3, Vector3};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use serde_json::{Value, json};
use std::fmt::Write as _;
use std::path::Path;

const CELLS: usize = 3;
const RADIUS: f64 = 1e-3;
const OVERLAP: f64 = 1e-3 * RADIUS;
const STEPS: u64 = 4000;
const ALPHA_MAX_SEARCHED: f64 = 8.0;
/// Gain (in initial kinetic energies) that marks a run unstable. Not 1: near the
/// limit a stable run's measured energy swings by 1/(1 − (ωΔt/2)²) of its top
/// mode's energy (Verlet conserves a shadow energy, not E). Not much more than 10
/// either: with friction an unstable rotational mode grows only until the contacts
/// slide, and then holds at a few hundred times the initial energy, bounded but
/// wrong.
const ENERGY_GAIN_LIMIT: f64 = 10.0;

/// One law's result (the rows of `accuracy-cost/stable_alpha.csv`).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct StableRow {
    pub law: String,
    /// Largest stable α found (bisection to 0.5 %); empty if stable up to `searched_to`.
    pub alpha_max: Option<f64>,
    pub searched_to: f64,
    /// The closed-form limit where one exists.
    pub theory: Option<f64>,
    pub note: String,
}

struct Law {
    label: String,
    contact: Value,
    rotation: bool,
    /// Use the NiAl material (with Hollomon hardening) instead of steel.
    plastic: bool,
    theory: bool,
}

/// The rows of the study: the chosen combinations below, then every law of the
/// registry (`contact::registry`) that none of them uses, with the registry's
/// parameters (a normal law alone; a tangential law beside Hertz, with rotation).
fn laws() -> Vec<Law> {
    let mut rows = chosen();
    let normal_of = |row: &Law| serde_json::from_value::<NormalLaw>(row.contact["normal"].clone());
    let tangential_of =
        |row: &Law| serde_json::from_value::<TangentialLaw>(row.contact["tangential"].clone()).ok();
    let mut enrolled = Vec::new();
    for n in registry::normal_laws() {
        if !rows
            .iter()
            .any(|r| normal_of(r).is_ok_and(|m| m.name() == n.name()))
        {
            enrolled.push(Law {
                label: format!("{} (registry parameters)", n.name()),
                contact: json!({ "normal": n }),
                rotation: false,
                plastic: n.needs().hollomon,
                theory: false,
            });
        }
    }
    for t in registry::tangential_laws() {
        if !rows
            .iter()
            .any(|r| tangential_of(r).is_some_and(|u| u.name() == t.name()))
        {
            let mut tangential = serde_json::to_value(t).expect("a law serialises");
            tangential["friction"] = json!(0.5);
            enrolled.push(Law {
                label: format!("hertz + {} (registry parameters), rotation", t.name()),
                contact: json!({"normal": {"law": "hertz"}, "tangential": tangential}),
                rotation: true,
                plastic: false,
                theory: false,
            });
        }
    }
    rows.extend(enrolled);
    rows
}

/// The combinations the study was designed around (the linear laws' k_n suits the
/// lattice's 1 mm steel spheres).
fn chosen() -> Vec<Law> {
    let law = |label: &str, contact: Value, rotation, plastic, theory| Law {
        label: label.to_string(),
        contact,
        rotation,
        plastic,
        theory,
    };
    let k = 1e6; // N/m, the linear laws' k_n
    let hertz = json!({"law": "hertz"});
    let linear = json!({"law": "linear", "stiffness": k});
    vec![
        law("linear", json!({"normal": linear}), false, false, true),
        law(
            "linear + cundall_strack (k_s = 2/7 k_n), rotation",
            json!({"normal": linear, "tangential": {"law": "cundall_strack", "stiffness": k * 2.0 / 7.0, "friction": 0.5}}),
            true,
            false,
            false,
        ),
        law(
            "linear + walton_braun tangential (k₀ = 2/7 k_n), rotation",
            json!({"normal": linear, "tangential": {"law": "walton_braun", "stiffness": k * 2.0 / 7.0, "friction": 0.5}}),
            true,
            false,
            false,
        ),
        law(
            "linear + liggghts_history, rotation",
            json!({"normal": linear, "tangential": {"law": "liggghts_history", "friction": 0.5}}),
            true,
            false,
            false,
        ),
        law("hertz", json!({"normal": hertz}), false, false, true),
        law(
            "hertz, critical_fraction ξ = 0.5",
            json!({"normal": hertz, "damping": {"kind": "critical_fraction", "xi": 0.5}}),
            false,
            false,
            false,
        ),
        law(
            "hertz + mindlin_deresiewicz, rotation",
            json!({"normal": hertz, "tangential": {"law": "mindlin_deresiewicz", "friction": 0.5}}),
            true,
            false,
            false,
        ),
        law(
            "hertz + mindlin_no_slip, rotation",
            json!({"normal": hertz, "tangential": {"law": "mindlin_no_slip", "friction": 0.5}}),
            true,
            false,
            false,
        ),
        law(
            "hertz + liggghts_history, rotation",
            json!({"normal": hertz, "tangential": {"law": "liggghts_history", "friction": 0.5}}),
            true,
            false,
            false,
        ),
        law(
            "hertz + coulomb, rotation",
            json!({"normal": hertz, "tangential": {"law": "coulomb", "friction": 0.5}}),
            true,
            false,
            false,
        ),
        law(
            "hertz + haff_werner (γ_s = 10 N·s/m), rotation",
            json!({"normal": hertz, "tangential": {"law": "haff_werner", "damping": 10.0, "friction": 0.5}}),
            true,
            false,
            false,
        ),
        law(
            "kuwabara_kono (A = 2e-8 s)",
            json!({"normal": {"law": "kuwabara_kono", "dissipation_time": 2e-8}}),
            false,
            false,
            false,
        ),
        law(
            "walton_braun (k₁ = k, k₂ = 2k)",
            json!({"normal": {"law": "walton_braun", "loading_stiffness": k, "unloading_stiffness": 2.0 * k}}),
            false,
            false,
            false,
        ),
        law(
            "hysteretic (γ = 0.5)",
            json!({"normal": {"law": "hysteretic", "stiffness": k, "hysteresis": 0.5}}),
            false,
            false,
            false,
        ),
        law(
            "storakers (NiAl, m = 0.2)",
            json!({"normal": {"law": "storakers"}}),
            false,
            true,
            false,
        ),
        law(
            "storakers, min_with_hertz (NiAl, m = 0.2)",
            json!({"normal": {"law": "storakers", "min_with_hertz": true}}),
            false,
            true,
            false,
        ),
        law(
            "storakers, min_with_hertz + storakers tangential (β = 0.5), rotation",
            json!({"normal": {"law": "storakers", "min_with_hertz": true}, "tangential": {"law": "storakers", "beta": 0.5, "friction": 0.5}}),
            true,
            true,
            false,
        ),
    ]
}

/// The FCC lattice's sites in a periodic box of side `CELLS · a`, a the cubic cell.
fn sites(a: f64) -> Vec<[f64; 3]> {
    let basis = [
        [0.0, 0.0, 0.0],
        [0.5, 0.5, 0.0],
        [0.5, 0.0, 0.5],
        [0.0, 0.5, 0.5],
    ];
    let mut out = Vec::new();
    for i in 0..CELLS {
        for j in 0..CELLS {
            for k in 0..CELLS {
                for b in basis {
                    // A quarter cell inwards so no centre sits on a periodic face.
                    out.push([
                        (i as f64 + b[0] + 0.25) * a,
                        (j as f64 + b[1] + 0.25) * a,
                        (k as f64 + b[2] + 0.25) * a,
                    ]);
                }
            }
        }
    }
    out
}

// NiAl's Poisson ratio 0.318 (Rojek 2016 Table 2) is a material constant, not 1/π.
#[allow(clippy::approx_constant)]
fn scene_json(law: &Law, velocities: &[([f64; 3], [f64; 3])]) -> Value {
    let a = std::f64::consts::SQRT_2 * (2.0 * RADIUS - OVERLAP);
    let material = if law.plastic {
        // Rojek 2016 Table 2.
        json!({"name": "m", "density": 5910, "youngs_modulus": 183e9, "poisson_ratio": 0.318,
               "hollomon": {"exponent": 0.2, "yield_stress": 800e6}})
    } else {
        json!({"name": "m", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3})
    };
    let particles: Vec<Value> = sites(a)
        .iter()
        .zip(
            velocities
                .iter()
                .chain(std::iter::repeat(&([0.0; 3], [0.0; 3]))),
        )
        .map(|(x, (v, w))| {
            let mut p = json!({"position": x, "radius": RADIUS, "material": "m", "velocity": v});
            if law.rotation {
                p["omega"] = json!(w);
            }
            p
        })
        .collect();
    let side = CELLS as f64 * a;
    let mut scene = json!({
        "name": format!("stable-alpha lattice: {}", law.label),
        "materials": [material],
        "contact": law.contact,
        "particles": particles,
        "periodic": {"x": [0.0, side], "y": [0.0, side], "z": [0.0, side]},
        "stability": {"initial_overlap_tolerance": 0.01, "max_energy_growth": 1e12},
        "time_step": {"alpha": 0.2},
        "run": {"steps": STEPS}
    });
    if law.rotation {
        scene["rotation"] = json!({});
    }
    scene
}

/// Whether `law` runs `STEPS` steps at α without gaining energy; the error message
/// when it stops.
fn stable_at(law: &Law, velocities: &[([f64; 3], [f64; 3])], alpha: f64) -> Result<bool> {
    let mut s = scene::parse(&scene_json(law, velocities).to_string())?;
    s.time_step.alpha = Some(alpha);
    let mut built = scene::build(&s)?;
    let sim = &mut built.sim;
    let e0 = sim.mechanical_energy();
    let k0 = sim.kinetic_energy();
    for _ in 0..STEPS {
        if sim.step().is_err() {
            return Ok(false);
        }
        if sim.mechanical_energy() - e0 > ENERGY_GAIN_LIMIT * k0 {
            return Ok(false);
        }
    }
    Ok(true)
}

/// Random velocities and spins of about 1 % of δ₀ per oscillation period of the
/// normal springs alone, so the lattice vibrates in every mode without opening
/// contacts, and every law with the same normal law gets the same vibration.
fn vibration(law: &Law) -> Result<Vec<([f64; 3], [f64; 3])>> {
    let mut contact = law.contact.clone();
    if let Some(c) = contact.as_object_mut() {
        c.remove("tangential");
        c.remove("damping");
    }
    let normal_only = Law {
        label: law.label.clone(),
        contact,
        rotation: false,
        plastic: law.plastic,
        theory: law.theory,
    };
    let s = scene::parse(&scene_json(&normal_only, &[]).to_string())?;
    let built = scene::build(&s)?;
    let dt_cr = built
        .dt_estimate
        .ok_or_else(|| TampError::Other(format!("{}: no critical step estimate", law.label)))?
        / s.time_step.alpha();
    let v0 = 0.01 * OVERLAP * 2.0 / dt_cr;
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let mut draw =
        |scale: f64| -> [f64; 3] { [0; 3].map(|_| scale * (2.0 * rng.random::<f64>() - 1.0)) };
    Ok((0..built.sim.state().particles.len())
        .map(|_| (draw(v0), draw(v0 / RADIUS)))
        .collect())
}

/// The search on the study's first row, the frictionless linear FCC lattice: the one
/// row whose limit has a closed form (`fcc_linear_alpha_max`), on which the search is
/// checked (tests/studies.rs).
pub fn linear_lattice_limit() -> Result<Option<f64>> {
    let law = laws()
        .into_iter()
        .next()
        .filter(|l| l.label == "linear")
        .ok_or_else(|| {
            TampError::Other("the study's first row is not the linear lattice".into())
        })?;
    Ok(largest_stable_alpha(&law)?.0)
}

fn largest_stable_alpha(law: &Law) -> Result<(Option<f64>, String)> {
    let velocities = vibration(law)?;
    let mut lo = 0.01;
    if !stable_at(law, &velocities, lo)? {
        return Ok((Some(0.0), format!("unstable already at α = {lo}")));
    }
    let mut hi = 0.5;
    while stable_at(law, &velocities, hi)? {
        lo = hi;
        hi *= 2.0;
        if hi > ALPHA_MAX_SEARCHED {
            return Ok((None, String::new()));
        }
    }
    while (hi - lo) > 0.005 * lo {
        let mid = 0.5 * (lo + hi);
        if stable_at(law, &velocities, mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok((Some(lo), String::new()))
}

/// √(12/λ): the closed-form α_max of the frictionless linear lattice (module docs).
pub fn fcc_linear_alpha_max() -> f64 {
    let neighbours: Vec<Vector3<f64>> = [
        [1.0, 1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 0.0, 1.0],
        [1.0, 0.0, -1.0],
        [0.0, 1.0, 1.0],
        [0.0, 1.0, -1.0],
    ]
    .iter()
    .flat_map(|r| {
        let v = Vector3::from(*r) * 0.5; // in units of the cubic cell
        [v, -v]
    })
    .collect();
    let n = CELLS as i32;
    let mut lambda = 0.0f64;
    // Wave vectors allowed by the periodic box, q = 2π (h, k, l) / (CELLS a); 2·CELLS
    // per axis covers the reciprocal cell.
    for h in 0..2 * n {
        for k in 0..2 * n {
            for l in 0..2 * n {
                let q = Vector3::new(h as f64, k as f64, l as f64)
                    * (2.0 * std::f64::consts::PI / CELLS as f64);
                let d: Matrix3<f64> = neighbours
                    .iter()
                    .map(|r| {
                        let u = r.normalize();
                        (1.0 - q.dot(r).cos()) * u * u.transpose()
                    })
                    .sum();
                let top = d.symmetric_eigenvalues().max();
                lambda = lambda.max(top);
            }
        }
    }
    (12.0 / lambda).sqrt()
}

pub fn run(out: &Path) -> Result<u8> {
    let data_dir = out.join("accuracy-cost");
    crate::output::create_dir(&data_dir)?;
    let theory = fcc_linear_alpha_max();
    let mut rows = Vec::new();
    for law in laws() {
        eprint!("{:<58} ", law.label);
        let (alpha_max, note) = largest_stable_alpha(&law)?;
        eprintln!(
            "{}",
            alpha_max.map_or(format!("> {ALPHA_MAX_SEARCHED}"), |a| format!("{a:.4}"))
        );
        rows.push(StableRow {
            law: law.label.clone(),
            alpha_max,
            searched_to: ALPHA_MAX_SEARCHED,
            theory: law.theory.then_some(theory),
            note,
        });
    }
    super::write_csv(&data_dir.join("stable_alpha.csv"), &rows)?;
    super::page::write(out)?;
    Ok(0)
}

/// The page's section on the stable-α search.
pub fn section(rows: &[StableRow]) -> String {
    let mut s = String::from(
        "## Largest stable α per law

`tamp study stable-alpha`: 108 equal spheres on a face-centred cubic lattice,
periodic on all axes, every sphere pressed into its 12 neighbours by δ₀ = 10⁻³ R and
set vibrating in all modes (random velocities and spins of about 1 % of δ₀ per
period); R = 1 mm steel (E = 200 GPa, ν = 0.3, ρ = 7800 kg/m³; the linear laws take
k_n = 10⁶ N/m), or NiAl (Rojek 2016 Table 2) for Storåkers; friction μ = 0.5. α_max
is the largest α = Δt/Δt_cr (bisection to 0.5 %) at which 4000 steps gain less than
10 times the initial kinetic energy (src/study/stable_alpha.rs). Δt_cr is tamp's
estimate at t = 0 (core/src/timestep.rs): it takes each particle's summed normal contact
stiffness, its summed tangential stiffness times the lever 1 + mR²/I of rotation,
and the damping ratio (Rojek eq 28).

| law | α_max | closed form |
|---|---|---|
",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} |",
            r.law,
            r.alpha_max
                .map_or(format!("> {}", r.searched_to), |a| format!(
                    "{a:.3}{}",
                    if r.note.is_empty() {
                        String::new()
                    } else {
                        format!(" ({})", r.note)
                    }
                )),
            r.theory
                .map(|t| format!("{t:.4} (√(12/λ), FCC lattice)"))
                .unwrap_or_else(|| "—".into())
        );
    }
    s.push_str(READING);
    s
}

const READING: &str = "
Reading the table:

- **Frictionless linear and Hertz lattices** reach the closed form √(12/λ) = √1.5 (λ = 8, the
  FCC lattice's top eigenvalue, longitudinal at the X point): tamp's estimate sums each
  particle's normal contact stiffnesses, and the lattice's fastest mode is 2/3 of that sum.
  The unit test `linear_lattice_limit_matches_the_closed_form` keeps it so.
- **Friction with rotation**: the fastest mode can be a rotational one, neighbours spinning
  against each other through their tangential springs, ω² up to Σ_c k_t (1 − (n_c·e)²) 2R²/I
  over the contacts. The estimate sums k_t over the contacts like it sums k_n
  (core/src/simulation/critical_step.rs), which puts every row at α_max ≥ 1; the *largest*
  k_t times the lever 1 + mR²/I alone would miss this mode and leave the Mindlin laws
  (k_t ≈ 0.8 k_n) stable only well below α = 1. Rojek 2016
  §3.4 makes the same observation (with equal normal and tangential stiffness the
  rotational eigenfrequency exceeds the translational one) and scales the rotational
  inertia by 10 instead (`rotation.inertia_scale`), which lowers the lever 1 + mR²/I.
- **Haff–Werner** viscous friction is explicit: its limit 2m/(γ_s L) holds for one
  dashpot, while a particle's 12 dashpots act on it together, so the estimate divides it by
  the number of contacts.
- **Coulomb (Zhong VII) and hysteretic (Zhong V)** switch force on the sign of a rate (slip
  velocity, dδ/dt). In contacts that stay closed the sign flips every few steps, and each
  flip applies a force jump of μF_n (or 2γk_nδ) for one step: the lattice gains energy at a
  rate that grows with Δt, a chatter rather than an exponential mode, and no stiffness in
  the estimate describes it. These laws suit collisions; for persistent contacts prefer a
  law with a tangential spring.
- **Damping** ξ = 0.5 lowers α_max from √1.5 to about 0.82 although eq 28 already shortens
  the estimate by √(1 + ξ²) − ξ = 0.618. Each contact's dashpot has the structure of its
  spring, so in the fastest mode they add up like the springs do, to a modal damping ratio
  of 2ξ = 1 here, whose eq 28 factor is √2 − 1 = 0.414: α_max = √1.5 · 0.414/0.618 = 0.82.
  With strong damping in a dense bed keep α well below 0.8.
- **Pure Storåkers** at tiny overlaps creates energy at every step size: there unloading is
  softer than loading, so each small cycle returns more work than it took
  (docs/models/storakers.md). With `min_with_hertz` it behaves like Hertz.
";

#[cfg(test)]
mod tests {
    use super::*;

    /// A law registered with closed-form examples gets a row without being named here.
    #[test]
    fn every_registered_law_has_a_row() {
        let rows = laws();
        for n in registry::normal_laws() {
            let normal = serde_json::to_value(n).unwrap();
            assert!(
                rows.iter()
                    .any(|r| r.contact["normal"]["law"] == normal["law"]),
                "{}",
                n.name()
            );
        }
        for t in registry::tangential_laws() {
            assert!(
                rows.iter()
                    .any(|r| r.contact["tangential"]["law"] == t.name()),
                "{}",
                t.name()
            );
        }
    }

    #[test]
    fn fcc_closed_form_is_sqrt_three_halves() {
        approx::assert_relative_eq!(fcc_linear_alpha_max(), 1.5f64.sqrt(), max_relative = 1e-12);
    }
}
