//! Connecting the processes: timely's own handshake (process `i` connects to every process
//! before it and accepts every process after it; each connection starts with the connecting
//! process's index, a big-endian `u64`), done here so that it is quiet (timely prints its
//! progress on standard output, where our JSON goes) and gives up at a deadline instead of
//! retrying for ever.

use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::time::{Duration, Instant};

/// How long to wait between connection attempts.
const RETRY: Duration = Duration::from_millis(50);

/// One socket per process in process order, `None` at `me`; every peer connected before
/// `deadline`, or why not.
pub(crate) fn sockets(
    hosts: &[String],
    me: usize,
    deadline: Instant,
) -> Result<Vec<Option<TcpStream>>, String> {
    let listener = TcpListener::bind(hosts[me].as_str())
        .map_err(|e| format!("cannot listen on {} (process {me}): {e}", hosts[me]))?;
    listener
        .set_nonblocking(true)
        .map_err(|e| format!("listener: {e}"))?;
    let mut out: Vec<Option<TcpStream>> = (0..hosts.len()).map(|_| None).collect();
    for (i, host) in hosts.iter().enumerate().take(me) {
        let mut s = loop {
            match TcpStream::connect(host.as_str()) {
                Ok(s) => break s,
                Err(e) if Instant::now() >= deadline => {
                    return Err(format!("process {i} at {host} did not answer: {e}"));
                }
                Err(_) => std::thread::sleep(RETRY),
            }
        };
        s.set_nodelay(true).map_err(|e| format!("{host}: {e}"))?;
        s.write_all(&(me as u64).to_be_bytes())
            .map_err(|e| format!("{host}: {e}"))?;
        out[i] = Some(s);
    }
    let mut waiting = hosts.len() - me - 1;
    while waiting > 0 {
        match listener.accept() {
            Ok((mut s, _)) => {
                s.set_nonblocking(false)
                    .map_err(|e| format!("accept: {e}"))?;
                s.set_nodelay(true).map_err(|e| format!("accept: {e}"))?;
                s.set_read_timeout(Some(
                    deadline
                        .saturating_duration_since(Instant::now())
                        .max(RETRY),
                ))
                .map_err(|e| format!("accept: {e}"))?;
                let mut b = [0u8; 8];
                s.read_exact(&mut b)
                    .map_err(|e| format!("handshake: {e}"))?;
                s.set_read_timeout(None)
                    .map_err(|e| format!("accept: {e}"))?;
                let i = u64::from_be_bytes(b) as usize;
                match out.get_mut(i) {
                    Some(slot @ None) if i > me => {
                        *slot = Some(s);
                        waiting -= 1;
                    }
                    _ => return Err(format!("unexpected connection claiming process {i}")),
                }
            }
            Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => {
                if Instant::now() >= deadline {
                    let missing: Vec<String> = (me + 1..hosts.len())
                        .filter(|&i| out[i].is_none())
                        .map(|i| format!("{i} ({})", hosts[i]))
                        .collect();
                    return Err(format!(
                        "process(es) {} did not connect in time",
                        missing.join(", ")
                    ));
                }
                std::thread::sleep(RETRY);
            }
            Err(e) => return Err(format!("accept: {e}")),
        }
    }
    Ok(out)
}

/// Timely's allocators for `threads` workers of process `me`, connected to the others.
pub(crate) fn allocators(
    hosts: &[String],
    me: usize,
    threads: usize,
    deadline: Instant,
) -> Result<
    (
        Vec<timely_communication::AllocatorBuilder>,
        Box<dyn std::any::Any + Send>,
    ),
    String,
> {
    use timely_communication::allocator::zero_copy::initialize::initialize_networking_from_sockets;
    use timely_communication::allocator::ProcessBuilder;
    let socks = sockets(hosts, me, deadline)?;
    let hooks = timely_communication::Hooks::default();
    let local =
        ProcessBuilder::new_typed_vector(threads, hooks.refill.clone(), hooks.spill.clone());
    let (builders, guard) = initialize_networking_from_sockets(local, socks, me, threads, hooks)
        .map_err(|e| format!("network: {e}"))?;
    Ok((
        builders
            .into_iter()
            .map(timely_communication::AllocatorBuilder::Tcp)
            .collect(),
        Box::new(guard),
    ))
}
