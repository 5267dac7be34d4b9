//! Progress with an ETA on stderr for long runs (indicatif). The bar appears only on
//! an interactive terminal and only once a stage has run for a second, so tests,
//! CI logs and short runs stay quiet.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

pub struct Progress {
    bar: ProgressBar,
    started: Instant,
    show: bool,
    shown: bool,
}

impl Progress {
    /// A bar for `stage` that will count to `len`.
    pub fn new(stage: &str, len: u64, quiet: bool) -> Self {
        let bar = ProgressBar::with_draw_target(Some(len), ProgressDrawTarget::hidden());
        bar.set_style(
            ProgressStyle::with_template(
                "{prefix:>8} {bar:40} {pos}/{len}  {elapsed} elapsed, ETA {eta}",
            )
            .expect("static template"),
        );
        bar.set_prefix(stage.to_string());
        Progress {
            bar,
            started: Instant::now(),
            show: !quiet && std::io::stderr().is_terminal(),
            shown: false,
        }
    }

    pub fn set(&mut self, position: u64) {
        if self.show && !self.shown && self.started.elapsed() > Duration::from_secs(1) {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
        self.bar.set_position(position);
    }

    pub fn finish(self) {
        self.bar.finish_and_clear();
    }
}
