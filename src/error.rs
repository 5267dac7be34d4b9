//! The error kinds of tamp and the exit codes the CLI contract maps them to:
//! 2 for bad input (the message names the field and the rule), 3 for a run that
//! became unstable (the message names the particle or contact and the step), 128 +
//! the signal's number for a run stopped by SIGINT or SIGTERM.

use thiserror::Error;

#[derive(Debug, Error)]
pub enum TampError {
    /// Bad input: `path` is the JSON path (or CLI argument) and `rule` what it broke.
    #[error("{path}: {rule}")]
    Input { path: String, rule: String },

    /// Several input errors found in one pass; each line is `path: rule`.
    #[error("{}", .0.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n"))]
    InputMany(Vec<TampError>),

    /// The run stopped because it became unstable; nothing non-finite was written.
    #[error("unstable at step {step} (t = {time:.6e} s): {what}")]
    Unstable { step: u64, time: f64, what: String },

    /// SIGINT or SIGTERM stopped the run after a whole step; `next` says what was
    /// saved and how to go on.
    #[error("stopped by {} after step {step} (t = {time:.6e} s): {next}", crate::interrupt::name(*.signal))]
    Interrupted {
        signal: i32,
        step: u64,
        time: f64,
        next: String,
    },

    #[error("{context}: {source}")]
    Io {
        context: String,
        #[source]
        source: std::io::Error,
    },

    /// A verification case could not be evaluated (distinct from a case that fails).
    #[error("{0}")]
    Other(String),
}

impl TampError {
    pub fn input(path: impl Into<String>, rule: impl Into<String>) -> Self {
        TampError::Input {
            path: path.into(),
            rule: rule.into(),
        }
    }

    /// The input errors this stands for, one by one (itself when it is one).
    pub fn into_list(self) -> Vec<TampError> {
        match self {
            TampError::InputMany(list) => list,
            other => vec![other],
        }
    }

    pub fn io(context: impl Into<String>, source: std::io::Error) -> Self {
        TampError::Io {
            context: context.into(),
            source,
        }
    }

    /// Exit code of the CLI contract (docs/architecture.md).
    pub fn exit_code(&self) -> i32 {
        match self {
            TampError::Input { .. } | TampError::InputMany(_) => 2,
            TampError::Unstable { .. } => 3,
            TampError::Interrupted { signal, .. } => 128 + signal,
            TampError::Io { .. } | TampError::Other(_) => 1,
        }
    }
}

pub type Result<T> = std::result::Result<T, TampError>;

/// Every field a peer code cannot express, as one input error with one
/// `path: cannot export to PEER: why` line per field.
pub fn cannot_export(peer: &str, list: Vec<(String, String)>) -> TampError {
    let mut errors: Vec<TampError> = list
        .into_iter()
        .map(|(path, why)| TampError::input(path, format!("cannot export to {peer}: {why}")))
        .collect();
    if errors.len() == 1 {
        errors.pop().expect("one error")
    } else {
        TampError::InputMany(errors)
    }
}

/// Input rules broken, collected in one pass: each `json.path: rule, got value`.
pub struct Errors(pub Vec<TampError>);

impl Errors {
    pub fn push(&mut self, path: impl Into<String>, rule: impl Into<String>) {
        self.0.push(TampError::input(path, rule));
    }

    pub fn positive(&mut self, path: impl Into<String>, value: f64) {
        if !(value > 0.0 && value.is_finite()) {
            self.push(path, format!("must be > 0 and finite, got {value:e}"));
        }
    }

    pub fn non_negative(&mut self, path: impl Into<String>, value: f64) {
        if !(value >= 0.0 && value.is_finite()) {
            self.push(path, format!("must be >= 0 and finite, got {value:e}"));
        }
    }

    /// Ok when nothing was found; the one error, or all of them.
    pub fn finish(mut self) -> Result<()> {
        match self.0.len() {
            0 => Ok(()),
            1 => Err(self.0.pop().unwrap()),
            _ => Err(TampError::InputMany(self.0)),
        }
    }

    pub fn finite3(&mut self, path: impl Into<String>, v: &[f64; 3]) {
        if !v.iter().all(|c| c.is_finite()) {
            self.push(path, format!("must be finite, got {v:?}"));
        }
    }
}
