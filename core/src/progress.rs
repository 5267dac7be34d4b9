//! Progress with an ETA on stderr for long runs (indicatif). The bar appears only on
//! an interactive terminal and only once a stage has run for a second, so tests and
//! short runs stay quiet; where stderr is a log (CI, `nohup`), a line with the same
//! numbers is written every `LOG_EVERY` instead, so a run of hours can be followed.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// `--quiet` for stages that run deep inside the scene build (generation), where
/// threading the flag through every caller of `scene::build` would serve no one.
static QUIET: AtomicBool = AtomicBool::new(false);

/// `--quiet` for every progress made from now on (false lets them report again).
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, Ordering::Relaxed);
}

/// Log lines even on a terminal: set while several runs share stderr (`tamp verify`
/// running cases side by side), whose bars would overwrite each other.
static LINES_ONLY: AtomicBool = AtomicBool::new(false);

/// Log lines instead of bars, even on a terminal, for every progress made from now on.
pub fn set_lines_only(lines_only: bool) {
    LINES_ONLY.store(lines_only, Ordering::Relaxed);
}

const LOG_EVERY: Duration = Duration::from_secs(60);

/// Progress of one stage (a run's steps, a generator's insertions): a bar on a terminal after
/// the first second, a line every `LOG_EVERY` when stderr is a log, nothing when quiet.
pub struct Progress {
    bar: ProgressBar,
    stage: String,
    len: u64,
    started: Instant,
    show: bool,
    shown: bool,
    /// Log lines instead of a bar (stderr is not a terminal), and when the last was
    /// written, at which position.
    log: bool,
    logged: Instant,
    logged_at: u64,
    /// Units per second between the last two log lines.
    last_rate: Option<f64>,
}

impl Progress {
    /// A bar for `stage` that will count to `len`.
    pub fn new(stage: &str, len: u64, quiet: bool) -> Self {
        let quiet = quiet || QUIET.load(Ordering::Relaxed);
        let bar = ProgressBar::with_draw_target(Some(len), ProgressDrawTarget::hidden());
        bar.set_style(
            ProgressStyle::with_template(
                "{prefix:>8} {bar:40} {pos}/{len}  {elapsed} elapsed, ETA {eta}",
            )
            .expect("static template"),
        );
        bar.set_prefix(stage.to_string());
        let terminal = std::io::stderr().is_terminal() && !LINES_ONLY.load(Ordering::Relaxed);
        Progress {
            bar,
            stage: stage.to_string(),
            len,
            started: Instant::now(),
            show: !quiet && terminal,
            shown: false,
            log: !quiet && !terminal,
            logged: Instant::now(),
            logged_at: 0,
            last_rate: None,
        }
    }

    /// Report that `position` of the stage's `len` units are done.
    pub fn set(&mut self, position: u64) {
        if self.show && !self.shown && self.started.elapsed() > Duration::from_secs(1) {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
        self.bar.set_position(position);
        if self.log && self.logged.elapsed() >= LOG_EVERY && position > self.logged_at {
            let rate = (position - self.logged_at) as f64 / self.logged.elapsed().as_secs_f64();
            self.logged = Instant::now();
            self.logged_at = position;
            let elapsed = self.started.elapsed().as_secs_f64();
            let eta = eta(self.len.saturating_sub(position), rate, self.last_rate);
            self.last_rate = Some(rate);
            eprintln!(
                "{}: {position}/{} after {elapsed:.0} s, {eta}",
                self.stage, self.len
            );
        }
    }

    /// Remove the bar from the terminal at the end of the stage.
    pub fn finish(self) {
        self.bar.finish_and_clear();
    }
}

/// The time left for `remaining` units at the present `rate` (units/s, over the last
/// interval). A stage whose rate falls (random sequential insertion slows as the
/// packing nears its jamming limit) can only be bounded below by it: the ETA is then
/// given as "at least".
fn eta(remaining: u64, rate: f64, before: Option<f64>) -> String {
    let left = remaining as f64 / rate;
    match before {
        Some(r) if rate < 0.95 * r => {
            format!("ETA at least {left:.0} s (the rate fell from {r:.3e} to {rate:.3e} per s)")
        }
        _ => format!("ETA {left:.0} s"),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_falling_rate_gives_a_lower_bound_not_a_date() {
        assert_eq!(super::eta(100, 10.0, None), "ETA 10 s");
        assert_eq!(super::eta(100, 10.0, Some(10.2)), "ETA 10 s");
        assert_eq!(
            super::eta(100, 5.0, Some(10.0)),
            "ETA at least 20 s (the rate fell from 1.000e1 to 5.000e0 per s)"
        );
    }
}
