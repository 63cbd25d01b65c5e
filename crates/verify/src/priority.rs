//! Thread priority: the explicit engine yields the cores to the SAT engines in the portfolio.

/// Lower the calling thread's scheduling priority (nice 10; on Linux the nice value is per
/// thread and inherited by the threads it starts). Failure leaves the priority as it was.
#[cfg(target_os = "linux")]
#[allow(unsafe_code)] // reason: two FFI calls with integer arguments only (gettid, setpriority)
pub(crate) fn lower_priority() {
    // SAFETY: `gettid` has no preconditions and `setpriority` reads only its integer
    // arguments; neither touches memory of ours. An error (-1) is ignored on purpose.
    unsafe {
        let tid = libc::syscall(libc::SYS_gettid);
        if let Ok(tid) = libc::id_t::try_from(tid) {
            libc::setpriority(libc::PRIO_PROCESS, tid, 10);
        }
    }
}

/// Elsewhere the explicit engine keeps the default priority.
#[cfg(not(target_os = "linux"))]
pub(crate) fn lower_priority() {}
