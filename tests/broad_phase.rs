//! The linked-cell detector finds exactly the pairs brute force finds, on random
//! polydisperse clouds (size ratios up to 20, dense and sparse, any margin).

use proptest::prelude::*;
use tamp::detect::{brute, cells};
use tamp::particles::Vec3;
use tamp::space::Space;

fn cloud() -> impl Strategy<Value = (Vec<Vec3>, Vec<f64>, f64)> {
    (2usize..300, 1.0f64..20.0, 0.5f64..30.0, 0.0f64..0.5).prop_flat_map(
        |(n, ratio, box_size, margin)| {
            (
                prop::collection::vec(
                    (0.0..box_size, 0.0..box_size, 0.0..box_size)
                        .prop_map(|(x, y, z)| Vec3::new(x, y, z)),
                    n,
                ),
                prop::collection::vec(0.05f64..0.05 * ratio, n),
                Just(margin),
            )
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn cells_match_brute_force((positions, radii, margin) in cloud()) {
        let a = brute::candidate_pairs(&positions, &radii, margin, &Space::open());
        let b = cells::candidate_pairs(&positions, &radii, margin);
        prop_assert_eq!(a, b);
    }
}

#[test]
fn coincident_centres_are_found() {
    let p = vec![Vec3::zeros(), Vec3::zeros(), Vec3::new(10.0, 0.0, 0.0)];
    let r = vec![1.0, 1.0, 1.0];
    assert_eq!(cells::candidate_pairs(&p, &r, 0.0), vec![(0, 1)]);
}
