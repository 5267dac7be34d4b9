//! A probed collision against a recorded peer's, as the cases' quantities.

use crate::collision::Collision;
use crate::verify::Measured;

/// The three quantities a recorded peer collision is compared on, named
/// `restitution_<tag>`, `contact_duration_<tag>`, `max_overlap_<tag>` against the
/// peer's values in that order. The sampled overlap, since peer dumps are sampled.
pub fn against_peer(c: &Collision, tag: &str, peer: [f64; 3]) -> [Measured; 3] {
    [
        Measured::new(&format!("restitution_{tag}"), c.restitution, peer[0]),
        Measured::new(&format!("contact_duration_{tag}"), c.duration, peer[1]),
        Measured::new(
            &format!("max_overlap_{tag}"),
            c.max_sampled_overlap,
            peer[2],
        ),
    ]
}
