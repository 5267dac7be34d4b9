//! A criterion `Measurement` that reads the CPU time of the benchmark thread instead
//! of wall time. The machine is shared (two cores, other jobs running), and wall
//! time then mostly measures how long the thread waited for a core.
//!
//! The kernel's per-thread count (`/proc/thread-self/schedstat`, Linux only) advances
//! in scheduler ticks (4 ms here), so a bench using it must make each sample run for
//! ~300 ms or more (flat sampling, `measurement_time` ≈ 0.3 s × `sample_size`) to keep
//! that granularity below ~2 %.
//!
//! Shared by several bench binaries through `#[path = "common/cpu_time.rs"] mod
//! cpu_time;` (a file under a subdirectory of benches/ is not a bench target itself).

use criterion::measurement::{Measurement, ValueFormatter, WallTime};
use std::time::Duration;

/// CPU time consumed by the calling thread.
pub struct ThreadCpuTime;

fn thread_cpu_nanos() -> u64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .expect("/proc/thread-self/schedstat (Linux) gives the thread's CPU time")
}

impl Measurement for ThreadCpuTime {
    type Intermediate = u64;
    type Value = Duration;

    fn start(&self) -> u64 {
        thread_cpu_nanos()
    }
    fn end(&self, start: u64) -> Duration {
        Duration::from_nanos(thread_cpu_nanos() - start)
    }
    fn add(&self, a: &Duration, b: &Duration) -> Duration {
        *a + *b
    }
    fn zero(&self) -> Duration {
        Duration::ZERO
    }
    fn to_f64(&self, value: &Duration) -> f64 {
        value.as_nanos() as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        // Same unit (a duration) as wall time, so reuse its formatting.
        WallTime.formatter()
    }
}
