//! Timing one call: its wall-clock and process CPU time.

use crate::render::process_cpu_seconds;
use std::time::{Duration, Instant};

/// Wall-clock and process CPU time of one timed call.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// Elapsed real time.
    pub wall: Duration,
    /// CPU time of the whole process (user + system, every thread) during the call;
    /// `None` where the platform does not report it.
    pub cpu: Option<Duration>,
}

/// Runs `f` and measures it.
pub fn timed<R>(f: impl FnOnce() -> R) -> (R, Timing) {
    let cpu_before = process_cpu_seconds();
    let start = Instant::now();
    let r = f();
    let wall = start.elapsed();
    let cpu = match (cpu_before, process_cpu_seconds()) {
        (Some(a), Some(b)) => Some(Duration::from_secs_f64((b - a).max(0.0))),
        _ => None,
    };
    (r, Timing { wall, cpu })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn busy_work_takes_cpu_time() {
        let (sum, t) = timed(|| (0..20_000_000u64).map(std::hint::black_box).sum::<u64>());
        assert!(sum > 0);
        assert!(t.wall > Duration::ZERO);
        if let Some(cpu) = t.cpu {
            assert!(cpu > Duration::ZERO, "{t:?}");
        }
    }
}
