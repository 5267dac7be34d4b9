//! Pouring (insert blocks with a schedule): batches arrive on time, never overlap
//! the particles already present, and the energy they bring is booked as external
//! work, so the energy book still closes (dissipation ≥ 0).

use serde_json::json;
use tamp::scene;

#[test]
fn batches_arrive_on_schedule_and_the_energy_book_closes() {
    let s = json!({
        "seed": 7,
        "materials": [{"name": "m", "density": 2500}],
        "contact": {"normal": {"law": "linear", "stiffness": 1e3},
                    "damping": {"kind": "critical_fraction", "xi": 0.3}},
        "insert": [{"count": 60, "radius": {"min": 0.9e-3, "max": 1.1e-3}, "material": "m",
                    "region": {"lower": [0, 0, 0.02], "upper": [0.01, 0.01, 0.026]},
                    "speed": 0.05, "schedule": {"start": 0.0, "every": 0.02, "per_event": 10}}],
        "walls": [
            {"material": "m", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}},
            {"material": "m", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [1, 0, 0]}},
            {"material": "m", "shape": {"kind": "plane", "point": [0.01, 0, 0], "normal": [-1, 0, 0]}},
            {"material": "m", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}},
            {"material": "m", "shape": {"kind": "plane", "point": [0, 0.01, 0], "normal": [0, -1, 0]}}
        ],
        "gravity": [0, 0, -9.81],
        "time_step": {"alpha": 0.2},
        "run": {"duration": 0.3}
    });
    let built = scene::build(&scene::parse(&s.to_string()).unwrap()).unwrap();
    let mut sim = built.sim;
    assert_eq!(
        sim.state().particles.len(),
        0,
        "nothing is placed before the first event"
    );
    let mut counts = Vec::new();
    let mut worst = 0.0f64;
    sim.run_with(built.steps, |s| {
        counts.push((s.state().time, s.state().particles.len()));
        worst = worst.max(s.state().max_overlap_ratio);
    })
    .unwrap();
    assert_eq!(sim.state().particles.len(), 60, "all particles poured");
    // Ten per event, events at 0, 0.02, 0.04, …: after t = 0.05 exactly 30 are in.
    let at = |t: f64| counts.iter().find(|(time, _)| *time >= t).unwrap().1;
    assert_eq!(at(0.05), 30);
    assert!(worst < 0.05, "largest overlap ratio {worst}");
    assert!(sim.dissipated_energy() >= 0.0);
    assert!(sim.state().energy.external_work > 0.0);
}
