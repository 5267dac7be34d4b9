//! Tangential contact laws. An absent law (friction off) is `None` in
//! `ContactLaw`: no tangential velocity is computed and no history is stored.

pub mod cundall_strack;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TangentialLaw {
    CundallStrack { stiffness: f64 },
}

impl TangentialLaw {
    pub fn name(&self) -> &'static str {
        match self {
            TangentialLaw::CundallStrack { .. } => "cundall_strack",
        }
    }

    pub fn stiffness(&self) -> f64 {
        match *self {
            TangentialLaw::CundallStrack { stiffness } => stiffness,
        }
    }
}
