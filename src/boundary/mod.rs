//! Boundaries: rigid bodies of given shape that particles collide with (Zhong 2009
//! §3: simple shapes, z = f(x, y) surfaces, convex polygon sets), each with its own
//! material and motion.

pub mod shape;
