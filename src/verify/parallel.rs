//! The parallel map of the verification runner: independent runs (cases, or the
//! specimens and models of one case) on up to `jobs` threads, with the results in
//! the order of the inputs whatever order they finish in. Each run is single-threaded
//! and deterministic, so no result depends on the number of jobs.

use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// `items.iter().map(run).collect()`, on up to `jobs` threads that take the next
/// item as they come free (so put the longest first when the order is free).
pub fn map<T, R, F>(items: &[T], jobs: usize, run: F) -> Vec<R>
where
    T: Sync,
    R: Send,
    F: Fn(&T) -> R + Sync,
{
    let jobs = jobs.clamp(1, items.len().max(1));
    let next = AtomicUsize::new(0);
    let done: Mutex<Vec<Option<R>>> = Mutex::new(items.iter().map(|_| None).collect());
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            scope.spawn(|| {
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(item) = items.get(k) else { break };
                    let r = run(item);
                    done.lock().expect("no run panics holding it")[k] = Some(r);
                }
            });
        }
    });
    done.into_inner()
        .expect("no run panicked")
        .into_iter()
        .map(|r| r.expect("every item ran"))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::map;
    use std::time::Duration;

    #[test]
    fn results_come_in_the_order_of_the_inputs_whatever_order_they_finish_in() {
        // The first items sleep longest, so with several jobs they finish last.
        let items: Vec<u64> = (0..8).collect();
        for jobs in [1, 3, 8, 20] {
            let out = map(&items, jobs, |&k| {
                std::thread::sleep(Duration::from_millis(5 * (8 - k)));
                k * k
            });
            assert_eq!(out, vec![0, 1, 4, 9, 16, 25, 36, 49], "jobs = {jobs}");
        }
        assert!(map(&[] as &[u64], 4, |&k| k).is_empty());
    }
}
