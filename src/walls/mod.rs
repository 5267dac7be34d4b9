//! Boundaries. A wall is another contact geometry: the same contact law acts on
//! particle–wall contacts, with the wall's own material in the pair table.

pub mod plane;

pub use plane::PlaneWall;
