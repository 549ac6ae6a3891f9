//! Keeping student panics quiet while student code runs in-process: a panic that is caught
//! and reported (as a stability verdict, a failed strategy) should not also print its
//! message and backtrace from every thread it went through.

use crate::implementation::is_todo_panic;
use std::panic::PanicHookInfo;
use std::sync::{Arc, Mutex, MutexGuard};

/// Serialises users of the process-wide panic hook.
static HOOK_LOCK: Mutex<()> = Mutex::new(());

type Hook = Box<dyn Fn(&PanicHookInfo<'_>) + Sync + Send + 'static>;

/// While alive, panics raised in `exercises/` (and `todo!()` anywhere) print nothing;
/// every other panic still goes to the previous hook, so a failing assertion elsewhere in
/// the process keeps its message. Dropping the guard restores the previous hook. Guards in
/// several threads take turns, so the original hook is never lost.
///
/// Unlike [`crate::implementation::catch_quietly`], the guard is held by the thread that
/// waits for the student code, not by the code itself: a call that never returns (and so
/// never restores anything) cannot leave the hook replaced for good.
pub struct QuietPanics {
    previous: Option<Arc<Hook>>,
    _lock: MutexGuard<'static, ()>,
}

/// True for a panic raised by student code.
fn from_student(info: &PanicHookInfo<'_>) -> bool {
    is_todo_panic(info.payload())
        || info
            .location()
            .is_some_and(|l| l.file().replace('\\', "/").contains("exercises/"))
}

impl QuietPanics {
    /// Installs the filtering hook (waiting for any other guard to be dropped first).
    pub fn new() -> Self {
        let lock = HOOK_LOCK
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        let previous: Arc<Hook> = Arc::new(std::panic::take_hook());
        let forward = Arc::clone(&previous);
        std::panic::set_hook(Box::new(move |info| {
            if !from_student(info) {
                forward(info);
            }
        }));
        Self {
            previous: Some(previous),
            _lock: lock,
        }
    }
}

impl Default for QuietPanics {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for QuietPanics {
    fn drop(&mut self) {
        // Dropping the filtering hook releases its handle on the previous one.
        drop(std::panic::take_hook());
        if let Some(previous) = self.previous.take() {
            match Arc::try_unwrap(previous) {
                Ok(hook) => std::panic::set_hook(hook),
                Err(shared) => std::panic::set_hook(Box::new(move |info| shared(info))),
            }
        }
    }
}
