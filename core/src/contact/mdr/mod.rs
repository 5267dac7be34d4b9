//! The mechanically derived response (MDR) of Zunker & Kamrin for elastic–perfectly
//! plastic, optionally adhesive spheres, made for compaction to high relative density.
//!
//! Sources: W. Zunker & K. Kamrin 2024, J. Mech. Phys. Solids 183, 105492 (Part I: one
//! sphere pressed by rigid flats, by the method of dimensionality reduction) and
//! 105493 (Part II: the bulk elastic response once the free surface is used up);
//! W. Zunker, S. Dunatunga, S. Thakur, P. Tang & K. Kamrin 2025, engrXiv 4289 (the
//! screening of contacts through a third particle, the radius update's confinement
//! weight); LAMMPS 22 Jul 2025 `src/GRANULAR/gran_sub_mod_normal.cpp`
//! (`GranSubModNormalMDR`), `gran_sub_mod_damping.cpp` (`GranSubModDampingMDR`) and
//! `fix_granular_mdr.cpp`, read line by line. The papers themselves are not in tamp's
//! library: every formula below is the one LAMMPS evaluates, and docs/models/mdr.md
//! says which of them a closed form of Part I checks.
//! Convention: δ > 0 overlap; F > 0 repulsive; SI units.
//!
//! **Rigid flats.** A pair contact is two contacts of a sphere with a rigid flat, one
//! per particle ("side"), each evaluated with that particle's own apparent radius R
//! and initial radius R₀; the pair force is the mean of the two, times the contact's
//! weight w = max(1 − p, 0) (`penalty.rs`). `flat.rs` places the flat: it splits the
//! pair overlap δ between the sides.
//!
//! **One side** (`side.rs`), overlap δ_s of a sphere of apparent radius R on a flat:
//!   - the overlap splits into an MDR part and a bulk part (`bulk.rs` says when);
//!     δ_max is the largest MDR part so far;
//!   - mean pressure on the yield surface p_Y = Y (1.75 e^{−4.4 δ_max/R} + 1);
//!   - the side yields once the Hertz mean pressure 4E* √δ/(3π √R) exceeds p_Y,
//!     at δ_Y; then c_A = π(δ_Y² − δ_Y R);
//!   - elastic: a 1D indenter of height A = 4R and width B = 2R (the sphere itself),
//!     at depth δ_e = δ;
//!   - plastic: the contact radius a_max² = 2δ_max R − δ_max² + c_A/π, an elliptical
//!     indenter A = 4 p_Y a_max/E*, B = 2a_max submerged to A/2 at δ_max, and the
//!     depth δ_e = (δ − δ_max + A/2 + Δ_R)/(1 + 2Δ_R/A), where Δ_R is the elastic
//!     displacement of the sphere's centre under the load (Part I's correction);
//!   - the force of the indenter at depth δ_e (zero for δ_e ≤ 0),
//!     F = E* A B/4 [acos(1 − 2δ_e/A) − (2 − 4δ_e/A) √(δ_e/A − (δ_e/A)²)],
//!     Hertz's 4/3 E* √R δ^{3/2} at small elastic depths, and π p_Y a_max² on the
//!     plastic loading branch (δ_e = A/2): the yield pressure over the contact area;
//!   - with surface energy γ > 0, tensile springs on unloading (`adhesion.rs`).
//!
//! E* = E/(1 − ν²) is the modulus of one sphere against a rigid flat; G and κ are
//! the shear and bulk moduli.
//!
//! **Per particle** (`particle.rs`): the contact areas and cap volumes summed over the
//! particle's contacts give its free surface fraction ψ and geometric volume; while
//! ψ > ψ_b the apparent radius grows with the plastically displaced volume; below ψ_b
//! the bulk response adds F_B = κ A_con δ_B A_c / V_geo per side.
//!
//! **Damping** (`damping.rs`): LAMMPS's `damping mdr 1` (a dashpot scaled by
//! √(2 m* E* a)) or `damping mdr 2` (a constant coefficient while in contact).
//!
//! LAMMPS mapping: `pair granular mdr E ν Y γ ψ_b η damping mdr <1|2>`, the same
//! words in `fix wall/gran/region granular …` (LAMMPS's MDR works with region walls
//! only), `newton off`; the per-particle state is LAMMPS's `fix GRANULAR/MDR`.

pub mod adhesion;
pub mod bulk;
pub mod contact;
pub mod damping;
pub mod flat;
pub mod parameters;
pub mod particle;
pub mod penalty;
pub mod side;

pub use contact::{MdrContact, PairSides, WallSide};
pub use damping::MdrDamping;
pub use parameters::Mdr;
pub use particle::MdrParticles;
pub use side::SideHistory;
