//! Packing measures: pure functions of particle centres and radii (no dependence on
//! the simulation type), built on the exact volume of a ball inside a region.
//!
//! | module | measure |
//! |---|---|
//! | `region` | `V(ball ∩ region)` exactly for boxes, slabs, cylinders (any axis), spheres |
//! | `packing` | `φ = Σ_i V(ball_i ∩ region) / V(region)`, periodic images included |
//! | `bed` | bulk `φ = Σ_i V_i / (A H)` of a laterally periodic bed, H its half-density surface |
//! | `rve` | φ in a ball at the specimen's centre, clear of the walls (Rojek et al. 2016 §5) |
//! | `coordination` | `Z = Σ z_i / N` over counted particles, rattlers and walls excluded on request |
//! | `profile` | `1 − φ` in layers from a plane wall and in shells from a cylindrical wall |
//! | `segregation` | surface-layer composition, `S = σ/σ₀` over horizontal layers, Lacey's M |
//!
//! Definitions, formulas and their verification are in docs/measures.md.

pub mod bed;
pub mod coordination;
pub mod packing;
pub mod profile;
pub mod region;
pub mod rve;
pub mod sample;
pub mod segregation;

pub use bed::{Bed, bulk_packing_fraction};
pub use coordination::{Coordination, CoordinationOptions, coordination};
pub use packing::{packing_fraction, solid_volume};
pub use profile::{Layer, PlaneProfile, cylinder_wall_profile, plane_wall_profile};
pub use region::Region;
pub use rve::{WallSurface, largest_rve_radius, rve_packing_fraction, specimen_centre_rve};
pub use segregation::{
    Basis, BedExtent, LayerComposition, Segregation, SegregationSpec, SurfaceLayers, segregation,
    surface_layers,
};
