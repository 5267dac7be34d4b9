//! Packing measures: pure functions of particle centres and radii (no dependence on
//! the simulation type), built on the exact volume of a ball inside a region.
//! Definitions, formulas and their verification are in docs/measures.md.

pub mod coordination;
pub mod packing;
pub mod profile;
pub mod region;
pub mod rve;
pub mod segregation;

pub use coordination::{Coordination, CoordinationOptions, coordination};
pub use packing::{packing_fraction, solid_volume};
pub use profile::{Layer, PlaneProfile, cylinder_wall_profile, plane_wall_profile};
pub use region::Region;
pub use rve::{WallSurface, largest_rve_radius, rve_packing_fraction, specimen_centre_rve};
pub use segregation::{
    Basis, BedExtent, LayerComposition, Segregation, SegregationSpec, SurfaceLayers, segregation,
    surface_layers,
};
