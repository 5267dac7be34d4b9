//! Seed-to-seed spread of the energy_conservation_elastic statistics (justifies its
//! tolerances): `cargo run --release --example energy_order_seeds`.
use tamp::scene;
fn main() {
    let text =
        std::fs::read_to_string("verification/energy_conservation_elastic.scene.json").unwrap();
    for seed in [7u64, 8, 9, 10, 11] {
        let mut sc = scene::parse(&text).unwrap();
        sc.seed = seed;
        let dt0 = scene::build(&sc).unwrap().sim.dt;
        let t_end = dt0 * 1e5;
        let mut pts = vec![];
        for f in [2.0, 1.0, 0.5, 0.25] {
            let mut b = scene::build(&sc).unwrap();
            b.sim.dt = dt0 * f;
            let steps = (t_end / b.sim.dt) as u64;
            let e0 = b.sim.mechanical_energy();
            let mut mx = 0.0f64;
            for _ in 0..steps {
                b.sim.step().unwrap();
                mx = mx.max((b.sim.mechanical_energy() - e0).abs() / e0);
            }
            pts.push(((dt0 * f).ln(), mx.ln()));
        }
        let n = pts.len() as f64;
        let (sx, sy) = (
            pts.iter().map(|p| p.0).sum::<f64>(),
            pts.iter().map(|p| p.1).sum::<f64>(),
        );
        let sxy = pts.iter().map(|p| p.0 * p.1).sum::<f64>();
        let sxx = pts.iter().map(|p| p.0 * p.0).sum::<f64>();
        let slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
        println!(
            "seed {seed}: max err at dt0 {:.3e}, slope {:.3}",
            pts[1].1.exp(),
            slope
        );
    }
}
