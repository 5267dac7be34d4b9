//! The error kinds of tamp and the exit codes the CLI contract maps them to:
//! 2 for bad input (the message names the field and the rule), 3 for a run that
//! became unstable (the message names the particle or contact and the step), 128 +
//! the signal's number for a run stopped by SIGINT or SIGTERM.

use thiserror::Error;

/// Every way a tamp run or command can fail; [`TampError::exit_code`] maps each kind to
/// the exit status of the CLI.
#[derive(Debug, Error)]
pub enum TampError {
    /// Bad input: `path` is the JSON path (or CLI argument) and `rule` what it broke.
    #[error("{path}: {rule}")]
    Input {
        /// JSON path of the offending field (or the CLI argument).
        path: String,
        /// The rule the value broke, with the value found.
        rule: String,
    },

    /// Several input errors found in one pass; each line is `path: rule`.
    #[error("{}", .0.iter().map(|e| e.to_string()).collect::<Vec<_>>().join("\n"))]
    InputMany(Vec<TampError>),

    /// The run stopped because it became unstable; nothing non-finite was written.
    #[error("unstable at step {step} (t = {time:.6e} s): {what}")]
    Unstable {
        /// Step at which the instability was found.
        step: u64,
        /// Simulated time at that step, s.
        time: f64,
        /// Which particle or contact went wrong, and how.
        what: String,
    },

    /// SIGINT or SIGTERM stopped the run after a whole step; `next` says what was
    /// saved and how to go on.
    #[error("stopped by {} after step {step} (t = {time:.6e} s): {next}", crate::interrupt::name(*.signal))]
    Interrupted {
        /// Number of the signal received (SIGINT or SIGTERM).
        signal: i32,
        /// Last step completed before stopping.
        step: u64,
        /// Simulated time at the end of that step, s.
        time: f64,
        /// What was saved and how to resume from it.
        next: String,
    },

    /// A file or stream could not be read or written.
    #[error("{context}: {source}")]
    Io {
        /// What was being read or written when it failed, usually a file's path.
        context: String,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },

    /// A verification case could not be evaluated (distinct from a case that fails).
    #[error("{0}")]
    Other(String),
}

impl TampError {
    /// One bad-input error: the field at `path` broke `rule`.
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

    /// An I/O failure, with the context it happened in.
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

/// A result whose error is a [`TampError`].
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
    /// Record that the field at `path` broke `rule`.
    pub fn push(&mut self, path: impl Into<String>, rule: impl Into<String>) {
        self.0.push(TampError::input(path, rule));
    }

    /// Require `value` to be finite and strictly positive.
    pub fn positive(&mut self, path: impl Into<String>, value: f64) {
        if !(value > 0.0 && value.is_finite()) {
            self.push(path, format!("must be > 0 and finite, got {value:e}"));
        }
    }

    /// Require `value` to be finite and not negative.
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

    /// Require every component of the 3-vector `v` to be finite.
    pub fn finite3(&mut self, path: impl Into<String>, v: &[f64; 3]) {
        if !v.iter().all(|c| c.is_finite()) {
            self.push(path, format!("must be finite, got {v:?}"));
        }
    }
}
