//! When to spread a node's iterations over threads: decided by timing the first ones on the
//! calling thread.
//!
//! Whether threads pay depends on what an item costs, which only running it tells: a million
//! additions are bound by memory traffic and a second thread only competes for it, while a
//! hundred closest points on a curve take 0.1 ms each and split well however few they are. So
//! every loop first runs a *probe* on its own thread, over growing ranges (1, 2, 4, … items)
//! until [`PROBE_NANOS`] have passed or enough items have run, and then [`Probe::spread_chunk`]
//! says how to run the rest: on this thread, or over threads in tasks of about
//! [`TASK_NANOS`] each. The probe's items are part of the result, and the rest is joined in
//! iteration order, so results are the same for any thread count and any timing.

use std::time::{Duration, Instant};

/// How long the probe runs at most before deciding (it also stops at the caller's item bound).
const PROBE_NANOS: u128 = 100_000;

/// The time per item below which a loop stays on one thread: below it a loop is bound by
/// memory traffic (a few additions per item), and a second thread only competes for it.
pub(crate) const PARALLEL_ITEM_NANOS: f64 = 8.0;

/// The least estimated time of the remaining items for which waking other threads pays
/// (waking a sleeping worker and joining it costs tens of microseconds).
const SPREAD_MIN_NANOS: f64 = 200_000.0;

/// The time a parallel task should take: long against the cost of a task (about a
/// microsecond), short enough that two threads finish close together.
const TASK_NANOS: f64 = 50_000.0;

/// What the probe ran: how many items, in what time.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Probe {
    /// Items run, from the first.
    pub(crate) done: usize,
    /// The time they took.
    pub(crate) elapsed: Duration,
}

/// Runs `run(start, end)` on this thread over the growing ranges `0..1`, `1..3`, `3..7`, … of
/// `0..count`, until `max_items` items have run or [`PROBE_NANOS`] have passed (at least one
/// item runs when `count > 0`).
pub(crate) fn probe(count: usize, max_items: usize, mut run: impl FnMut(usize, usize)) -> Probe {
    let limit = count.min(max_items.max(1));
    let started = Instant::now();
    let mut done = 0;
    let mut step = 1;
    while done < limit {
        let end = done.saturating_add(step).min(limit);
        run(done, end);
        done = end;
        step = step.saturating_mul(2);
        if started.elapsed().as_nanos() >= PROBE_NANOS {
            break;
        }
    }
    Probe {
        done,
        elapsed: started.elapsed(),
    }
}

impl Probe {
    /// The measured time per item, in nanoseconds.
    fn item_nanos(&self) -> f64 {
        self.elapsed.as_secs_f64() * 1e9 / self.done.max(1) as f64
    }

    /// How many items each parallel task of the `remaining` items should take (at most
    /// `max_chunk`), or `None` when they should run on this thread: their items are too quick
    /// for threads to pay, or all of them together would take too little time.
    pub(crate) fn spread_chunk(&self, remaining: usize, max_chunk: usize) -> Option<usize> {
        let per_item = self.item_nanos();
        if remaining < 2 || per_item < PARALLEL_ITEM_NANOS {
            return None;
        }
        if per_item * (remaining as f64) < SPREAD_MIN_NANOS {
            return None;
        }
        let chunk = (TASK_NANOS / per_item).ceil() as usize;
        Some(chunk.clamp(1, max_chunk.max(1)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn probe_runs_growing_contiguous_ranges_from_the_start() {
        let mut ranges = Vec::new();
        let p = probe(10, 100, |s, e| ranges.push((s, e)));
        assert_eq!(ranges, [(0, 1), (1, 3), (3, 7), (7, 10)]);
        assert_eq!(p.done, 10);
    }

    #[test]
    fn probe_stops_at_its_item_bound_and_runs_at_least_one() {
        let mut last = 0;
        let p = probe(1000, 20, |_, e| last = e);
        assert_eq!((p.done, last), (20, 20));
        assert_eq!(probe(5, 0, |_, _| {}).done, 1);
        assert_eq!(probe(0, 10, |_, _| panic!("no items to run")).done, 0);
    }

    #[test]
    fn probe_stops_when_its_time_is_up() {
        let p = probe(1000, 1000, |_, _| {
            std::thread::sleep(Duration::from_micros(150));
        });
        assert_eq!(p.done, 1, "one slow item is enough to decide");
    }

    #[test]
    fn slow_items_are_spread_in_tasks_of_about_the_task_time() {
        // 100 µs an item: one item a task, whatever the item bound.
        let slow = Probe {
            done: 1,
            elapsed: Duration::from_micros(100),
        };
        assert_eq!(slow.spread_chunk(99, 16_384), Some(1));
        // 1 µs an item: 50 items a task, but never more than the caller's bound.
        let medium = Probe {
            done: 100,
            elapsed: Duration::from_micros(100),
        };
        assert_eq!(medium.spread_chunk(10_000, 16_384), Some(50));
        assert_eq!(medium.spread_chunk(10_000, 8), Some(8));
    }

    #[test]
    fn quick_items_and_little_work_stay_on_this_thread() {
        // 2 ns an item: memory-bound, never spread.
        let quick = Probe {
            done: 50_000,
            elapsed: Duration::from_micros(100),
        };
        assert_eq!(quick.spread_chunk(10_000_000, 16_384), None);
        // 1 µs an item but only 100 left: 0.1 ms, not worth waking a thread.
        let medium = Probe {
            done: 100,
            elapsed: Duration::from_micros(100),
        };
        assert_eq!(medium.spread_chunk(100, 16_384), None);
        // One item left.
        let slow = Probe {
            done: 1,
            elapsed: Duration::from_millis(10),
        };
        assert_eq!(slow.spread_chunk(1, 16_384), None);
    }
}
