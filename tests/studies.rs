//! Checks of the `tamp study` entries that run whole simulations: integration tests,
//! so that the library's unit-test build does not compile the force loop for every
//! combination of laws (docs/performance.md).

use tamp::accuracy::calibration::MODELS;
use tamp::study::accuracy_calibration::{fits, measure};
use tamp::study::stable_alpha::{fcc_linear_alpha_max, linear_lattice_limit};

/// The constants checked in are the ones the calibration measures now: a change of the
/// integrator or of a law that moves them fails here until the study is rerun and its
/// table and `MODELS` updated.
#[test]
fn checked_in_models_are_the_calibration() {
    let fitted = fits(&measure().unwrap());
    for f in &fitted {
        let model = MODELS.iter().find(|m| m.law == f.law).unwrap();
        let t = model
            .terms
            .iter()
            .find(|t| t.quantity == f.quantity)
            .unwrap();
        assert!(
            (t.p - f.p).abs() < 1e-12 && (t.c - f.c).abs() <= 1e-12 * f.c,
            "{}/{}: checked in p = {}, C = {}; measured p = {}, C = {}",
            f.law,
            f.quantity,
            t.p,
            t.c,
            f.p,
            f.c
        );
    }
    assert_eq!(fitted.len(), 4 * MODELS.len());
}

/// For the FCC nearest-neighbour lattice the top of the spectrum is λ = 8 (at the X
/// point, longitudinal), so α_max = √(12/8). The bisection on the frictionless linear
/// lattice finds the closed form: the search resolves 0.5 % and stops just below the
/// limit, where the 10× energy criterion fires within 0.3 % of it.
#[test]
fn stable_alpha_finds_the_linear_lattice_closed_form() {
    let found = linear_lattice_limit()
        .unwrap()
        .expect("a stable step was found");
    let exact = fcc_linear_alpha_max();
    assert!(
        found <= exact && found > 0.99 * exact,
        "found {found}, closed form {exact}"
    );
}
