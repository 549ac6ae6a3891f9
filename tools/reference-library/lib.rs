//! The reference's task table behind two C functions, for the handout's binaries to load
//! (`pbrlab::compiled_reference`): the library's ABI signature, which the loader compares
//! with its own before anything else crosses, and the table.

use std::sync::OnceLock;

/// [`pbrlab::compiled_reference::ABI_SYMBOL`]: writes the signature's length to `len` and
/// returns its bytes, which live as long as the library.
///
/// # Safety
/// `len` must be valid for a write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pbrlab_reference_abi(len: *mut usize) -> *const u8 {
    static SIGNATURE: OnceLock<String> = OnceLock::new();
    let signature = SIGNATURE.get_or_init(pbrlab::compiled_reference::abi_signature);
    // SAFETY: the caller passes a writable `usize`.
    unsafe { len.write(signature.len()) };
    signature.as_ptr()
}

/// [`pbrlab::compiled_reference::TASKS_SYMBOL`]: the reference's
/// [`TaskFns`](pbrlab::worksheet::TaskFns), to be read only by a build whose signature is
/// this library's.
#[unsafe(no_mangle)]
pub extern "C" fn pbrlab_reference_tasks() -> *const std::ffi::c_void {
    (&raw const pbrlab_solutions::TASKS).cast()
}
