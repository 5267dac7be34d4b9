//! Accuracy on demand: `time_step.accuracy` asks for a relative error of the impact
//! quantities (maximum overlap and force, contact duration, rebound velocity) and
//! gets the step that delivers it, from an error model per law calibrated against
//! the laws' impact closed forms (docs/accuracy-cost.md).

pub mod calibration;
pub mod damped_hertz;
pub mod impact;
pub mod model;
pub mod step;
pub mod velocity;
