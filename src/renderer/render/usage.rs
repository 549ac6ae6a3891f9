//! What this process has used so far, from `getrusage(RUSAGE_SELF)`: CPU time (the
//! renderer's paths per CPU-second) and peak resident memory (the grader's item analysis).

/// This process's resource usage so far; `None` where the platform does not report it.
#[cfg(unix)]
fn usage() -> Option<libc::rusage> {
    let mut usage = std::mem::MaybeUninit::<libc::rusage>::zeroed();
    // SAFETY: getrusage only writes into the struct we pass, which is large enough.
    let rc = unsafe { libc::getrusage(libc::RUSAGE_SELF, usage.as_mut_ptr()) };
    // SAFETY: getrusage returned 0, so it initialised the struct.
    (rc == 0).then(|| unsafe { usage.assume_init() })
}

/// CPU time (user + system) this process has used so far, in seconds, summed over all its
/// threads; `None` where the platform does not report it.
pub fn process_cpu_seconds() -> Option<f64> {
    #[cfg(unix)]
    {
        let usage = usage()?;
        let seconds = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
        Some(seconds(usage.ru_utime) + seconds(usage.ru_stime))
    }
    #[cfg(not(unix))]
    {
        None
    }
}

/// The most resident memory this process has held so far, in KiB (Linux's `ru_maxrss`);
/// `None` where the platform does not report it.
pub fn peak_resident_kib() -> Option<u64> {
    #[cfg(target_os = "linux")]
    {
        u64::try_from(usage()?.ru_maxrss).ok()
    }
    #[cfg(not(target_os = "linux"))]
    {
        None
    }
}
