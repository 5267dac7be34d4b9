//! Numbers written as text into other codes' inputs (LIGGGHTS and LAMMPS decks, data
//! files, the peer models the contact laws declare): Rust's `{:e}` form, the shortest
//! decimal that reads back to the same double, so a deck carries tamp's values exactly.

/// `%.17g`-equivalent: Rust's shortest round-trip form.
pub fn g(x: f64) -> String {
    format!("{x:e}")
}
