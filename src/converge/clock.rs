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
    let cpu_before = process_cpu_time();
    let start = Instant::now();
    let r = f();
    let wall = start.elapsed();
    let cpu = match (cpu_before, process_cpu_time()) {
        (Some(a), Some(b)) => Some(b.saturating_sub(a)),
        _ => None,
    };
    (r, Timing { wall, cpu })
}

/// CPU time the process has used so far (user + system), from `getrusage`.
#[cfg(unix)]
pub fn process_cpu_time() -> Option<Duration> {
    let mut usage = std::mem::MaybeUninit::<libc::rusage>::uninit();
    // SAFETY: getrusage writes a complete `rusage` into the pointer on success (return 0),
    // and we read it only then.
    let usage = unsafe {
        if libc::getrusage(libc::RUSAGE_SELF, usage.as_mut_ptr()) != 0 {
            return None;
        }
        usage.assume_init()
    };
    let tv = |t: libc::timeval| Duration::new(t.tv_sec as u64, (t.tv_usec as u32) * 1000);
    Some(tv(usage.ru_utime) + tv(usage.ru_stime))
}

/// CPU time is not measured on this platform.
#[cfg(not(unix))]
pub fn process_cpu_time() -> Option<Duration> {
    None
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
