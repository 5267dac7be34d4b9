//! SIGINT and SIGTERM during `tamp run`. The first signal is only recorded: the run
//! finishes the step it is in, writes a checkpoint when checkpoints are on, says
//! how to go on, and exits with 128 + the signal's number (130, 143), the shell's
//! convention. A second signal ends the process at once, for a run stuck in a
//! write. Commands that never install the handlers keep the default behaviour.

use signal_hook::consts::{SIGINT, SIGTERM};
use signal_hook::flag;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

static RECEIVED: AtomicUsize = AtomicUsize::new(0);
static ARMED: AtomicBool = AtomicBool::new(false);

/// Take over SIGINT and SIGTERM for the rest of the process.
pub fn install() -> std::io::Result<()> {
    for signal in [SIGINT, SIGTERM] {
        // The shutdown goes first: it fires only once the first signal armed it.
        flag::register_conditional_shutdown(signal, 128 + signal, &ARMED)?;
        flag::register_usize(signal, &RECEIVED, signal as usize)?;
        flag::register(signal, &ARMED)?;
    }
    Ok(())
}

/// The signal received, if any: an atomic load, cheap enough to ask every step.
pub fn received() -> Option<i32> {
    match RECEIVED.load(Ordering::Relaxed) {
        0 => None,
        signal => Some(signal as i32),
    }
}

/// The conventional name of a signal number, for messages.
pub fn name(signal: i32) -> &'static str {
    match signal {
        SIGINT => "SIGINT",
        SIGTERM => "SIGTERM",
        _ => "a signal",
    }
}
