//! Studies: sweeps over the numerical settings of existing scenes that answer "what
//! does accuracy cost, and where does the integration stop being stable". They
//! write CSV data and a page (docs/accuracy-cost.md when run with `--out docs`).

pub mod accuracy_cost;
pub mod page;
pub mod stable_alpha;
