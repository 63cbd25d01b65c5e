//! The HTTP/WebSocket server: the page's assets, one WebSocket per session, the checks that
//! keep other origins out, and the file watch that reloads the model.
//!
//! **Safety.** Binds the address given (127.0.0.1 by default). Every request's `Host` must
//! name this server (DNS rebinding), a WebSocket's `Origin`, when sent, must be this
//! server's, and the WebSocket needs the token printed in the URL. Each message is parsed
//! and validated; a bad one gets an error reply and the session goes on.

use crate::load::{self, Loaded, PageDiagnostic};
use crate::park::Parking;
use crate::protocol::{self, Request};
use crate::session::Session;
use axum::extract::ws::{Message, WebSocket, WebSocketUpgrade};
use axum::extract::{Query, State};
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::Router;
use serde_json::{json, Value};
use std::collections::HashMap;
use std::net::SocketAddr;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, SystemTime};
use tokio::sync::watch;

/// Largest WebSocket message the transport accepts; larger ones close the connection.
/// Messages between [`protocol::MAX_REQUEST`] and this get an error reply.
pub const MAX_FRAME: usize = 16 << 20;
/// How often the model file is polled for changes.
pub const WATCH_EVERY: Duration = Duration::from_millis(400);

/// The model as sessions see it: loaded, or the diagnostics that stopped it.
pub type Current = Result<Arc<Loaded>, Arc<Vec<PageDiagnostic>>>;

struct App {
    token: String,
    hosts: Vec<String>,
    current: watch::Receiver<Current>,
    sessions: AtomicU64,
    live: AtomicU64,
    parking: Parking,
}

/// Build the router for a model, with the allowed `Host` values and the token.
fn router(app: Arc<App>) -> Router {
    Router::new()
        .route("/", get(index))
        .route(
            "/app.js",
            get(|h: HeaderMap, s: State<Arc<App>>| asset(h, s, "app.js")),
        )
        .route(
            "/chart.js",
            get(|h: HeaderMap, s: State<Arc<App>>| asset(h, s, "chart.js")),
        )
        .route(
            "/wave.js",
            get(|h: HeaderMap, s: State<Arc<App>>| asset(h, s, "wave.js")),
        )
        .route(
            "/layout-worker.js",
            get(|h: HeaderMap, s: State<Arc<App>>| asset(h, s, "layout-worker.js")),
        )
        .route(
            "/style.css",
            get(|h: HeaderMap, s: State<Arc<App>>| asset(h, s, "style.css")),
        )
        .route(
            "/elk.js",
            get(|h: HeaderMap, s: State<Arc<App>>| asset(h, s, "elk.js")),
        )
        .route("/ws", get(ws))
        .route("/stats", get(stats))
        .with_state(app)
}

fn host_ok(app: &App, h: &HeaderMap) -> bool {
    h.get(header::HOST)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| app.hosts.iter().any(|a| a == v))
}

fn refuse(code: StatusCode, why: &str) -> Response {
    (
        code,
        [(header::CONTENT_TYPE, "text/plain; charset=utf-8")],
        why.to_string(),
    )
        .into_response()
}

async fn index(
    State(app): State<Arc<App>>,
    h: HeaderMap,
    Query(q): Query<HashMap<String, String>>,
) -> Response {
    if !host_ok(&app, &h) {
        return refuse(StatusCode::FORBIDDEN, "unknown Host");
    }
    if q.get("token").is_none_or(|t| !same(t, &app.token)) {
        return refuse(
            StatusCode::FORBIDDEN,
            "open the URL that `statecheck serve` printed (it carries the access token)",
        );
    }
    (
        [
            (header::CONTENT_TYPE, "text/html; charset=utf-8"),
            (header::CACHE_CONTROL, "no-store"),
        ],
        crate::assets::INDEX,
    )
        .into_response()
}

async fn asset(h: HeaderMap, State(app): State<Arc<App>>, name: &'static str) -> Response {
    if !host_ok(&app, &h) {
        return refuse(StatusCode::FORBIDDEN, "unknown Host");
    }
    let (ty, body) = crate::assets::get(name);
    ([(header::CONTENT_TYPE, ty)], body).into_response()
}

async fn stats(
    State(app): State<Arc<App>>,
    h: HeaderMap,
    Query(q): Query<HashMap<String, String>>,
) -> Response {
    if !host_ok(&app, &h) || q.get("token").is_none_or(|t| !same(t, &app.token)) {
        return refuse(StatusCode::FORBIDDEN, "forbidden");
    }
    let body = json!({
        "sessions_opened": app.sessions.load(Ordering::Relaxed),
        "sessions_live": app.live.load(Ordering::Relaxed),
        "rss_bytes": rss_bytes(),
    });
    (
        [(header::CONTENT_TYPE, "application/json")],
        body.to_string(),
    )
        .into_response()
}

/// Resident memory of this process (Linux; `None` elsewhere).
pub fn rss_bytes() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = s.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

/// Constant-time comparison, so the token cannot be guessed a byte at a time.
fn same(a: &str, b: &str) -> bool {
    a.len() == b.len()
        && a.bytes()
            .zip(b.bytes())
            .fold(0u8, |acc, (x, y)| acc | (x ^ y))
            == 0
}

async fn ws(
    State(app): State<Arc<App>>,
    h: HeaderMap,
    Query(q): Query<HashMap<String, String>>,
    up: WebSocketUpgrade,
) -> Response {
    if !host_ok(&app, &h) {
        return refuse(StatusCode::FORBIDDEN, "unknown Host");
    }
    if let Some(origin) = h.get(header::ORIGIN) {
        let ok = origin
            .to_str()
            .ok()
            .is_some_and(|o| app.hosts.iter().any(|a| o == format!("http://{a}")));
        if !ok {
            return refuse(
                StatusCode::FORBIDDEN,
                "requests from other origins are refused",
            );
        }
    }
    if q.get("token").is_none_or(|t| !same(t, &app.token)) {
        return refuse(StatusCode::FORBIDDEN, "missing or wrong token");
    }
    let resume = q.get("resume").cloned();
    up.max_message_size(MAX_FRAME)
        .max_frame_size(MAX_FRAME)
        .on_upgrade(move |socket| session(app, socket, resume))
}

/// The first message: the model (or its diagnostics), the session number and its resume key
/// (128 random bits in hex).
fn hello(cur: &Current, id: u64, key: &str) -> String {
    match cur {
        Ok(l) => format!(
            "{{\"type\":\"model\",\"session\":{id},\"resume\":\"{key}\",\"model\":{}}}",
            l.description
        ),
        Err(d) => json!({"type": "diagnostics", "session": id, "resume": key, "diagnostics": &**d})
            .to_string(),
    }
}

/// The session for a new connection and the state message to send: the parked session of
/// `key` (its inputs re-applied to the current model) or a fresh one.
fn open_session(cur: &Current, parked: Option<Session>) -> (Option<Session>, Option<Value>) {
    let Ok(l) = cur else {
        return (None, None);
    };
    let Some(old) = parked else {
        let s = Session::new(Arc::clone(l));
        let v = protocol::state(&s, None, Some(0), &[]);
        return (Some(s), Some(v));
    };
    let (s, ticks, note) = old.reapply(Arc::clone(l));
    let mut v = protocol::state(&s, None, Some(0), &ticks);
    v["note"] = json!(note);
    (Some(s), Some(v))
}

async fn session(app: Arc<App>, mut socket: WebSocket, resume: Option<String>) {
    let id = app.sessions.fetch_add(1, Ordering::Relaxed) + 1;
    app.live.fetch_add(1, Ordering::Relaxed);
    let mut rx = app.current.clone();
    let cur = rx.borrow_and_update().clone();
    // A reload presents its session's key: resume that session (same key); otherwise a new
    // session gets a new random key.
    let parked = resume.as_deref().and_then(|k| app.parking.take(k));
    let key = match (&parked, resume) {
        (Some(_), Some(k)) => k,
        _ => random_token(),
    };
    let (mut sess, first) = open_session(&cur, parked);
    let mut shelved: Option<Session> = None;
    let mut ok = socket
        .send(Message::Text(hello(&cur, id, &key).into()))
        .await
        .is_ok();
    if let Some(v) = first {
        ok = ok && send(&mut socket, v).await;
    }
    let (vtx, mut vrx) = tokio::sync::mpsc::unbounded_channel::<Value>();
    let verifying = Arc::new(std::sync::atomic::AtomicBool::new(false));
    while ok {
        tokio::select! {
            Some(v) = vrx.recv() => {
                if v["type"] == "verify_done" {
                    verifying.store(false, Ordering::Relaxed);
                }
                ok = send(&mut socket, v).await;
            }
            msg = socket.recv() => {
                let reply = match msg {
                    None | Some(Err(_)) | Some(Ok(Message::Close(_))) => break,
                    Some(Ok(Message::Text(t))) => match protocol::parse(t.as_str()) {
                        Ok(Request::Verify { id, engine, timeout_s }) => {
                            start_verify(&sess, &verifying, &vtx, id, engine.as_deref(), timeout_s)
                        }
                        _ => handle(&mut sess, t.as_str()),
                    },
                    Some(Ok(Message::Binary(b))) => protocol::error(None, "malformed", &format!("binary message of {} bytes; requests are JSON text", b.len())),
                    Some(Ok(_)) => continue,
                };
                ok = send(&mut socket, reply).await;
            }
            changed = rx.changed() => {
                if changed.is_err() { break; }
                let cur = rx.borrow_and_update().clone();
                // The inputs so far are re-applied to the changed model when they still apply.
                // While the file does not check, the session waits on the shelf.
                let prev = sess.take().or(shelved.take());
                let first;
                if cur.is_err() {
                    shelved = prev;
                    first = None;
                } else {
                    (sess, first) = open_session(&cur, prev);
                }
                ok = socket.send(Message::Text(hello(&cur, id, &key).into())).await.is_ok();
                if let Some(v) = first {
                    ok = ok && send(&mut socket, v).await;
                }
            }
        }
    }
    if let Some(s) = sess.or(shelved) {
        if s.ticks() > 0 {
            app.parking.park(key, s);
        }
    }
    app.live.fetch_sub(1, Ordering::Relaxed);
}

/// Start a verification of the session's model on a blocking thread, its messages sent
/// through `tx`; one at a time per session.
fn start_verify(
    sess: &Option<Session>,
    verifying: &Arc<std::sync::atomic::AtomicBool>,
    tx: &tokio::sync::mpsc::UnboundedSender<Value>,
    id: Option<u64>,
    engine: Option<&str>,
    timeout_s: Option<u64>,
) -> Value {
    let Some(s) = sess else {
        return protocol::error(
            id,
            "no_model",
            "the model does not check; fix it and save the file",
        );
    };
    let engine = match crate::verify::engine(engine) {
        Ok(e) => e,
        Err(m) => return protocol::error(id, "bad_input", &m),
    };
    if verifying.swap(true, Ordering::Relaxed) {
        return protocol::error(
            id,
            "busy",
            "a verification is already running in this session",
        );
    }
    let loaded = Arc::clone(s.loaded());
    let tx = tx.clone();
    let timeout = timeout_s.unwrap_or(crate::verify::DEFAULT_TIMEOUT_S);
    tokio::task::spawn_blocking(move || {
        crate::verify::run(loaded, engine, timeout, &|v| {
            let _ = tx.send(v);
        });
    });
    json!({"type": "verify_started", "id": id, "engine": engine.as_str(), "timeout_s": timeout.min(crate::verify::MAX_TIMEOUT_S)})
}

async fn send(socket: &mut WebSocket, v: Value) -> bool {
    socket
        .send(Message::Text(v.to_string().into()))
        .await
        .is_ok()
}

/// Answer one request (the session is kept whatever the outcome).
pub fn handle(sess: &mut Option<Session>, text: &str) -> Value {
    let req = match protocol::parse(text) {
        Ok(r) => r,
        Err(e) => return e,
    };
    let Some(s) = sess.as_mut() else {
        return protocol::error(
            None,
            "no_model",
            "the model does not check; fix it and save the file",
        );
    };
    let fail = |id, e: crate::session::Error| {
        protocol::error(id, &format!("{:?}", e.kind).to_lowercase(), &e.message)
    };
    match req {
        Request::Describe { id } => {
            let d: Value = serde_json::from_str(&s.loaded().description).unwrap_or(Value::Null);
            json!({"type": "model", "id": id, "model": d})
        }
        Request::Set { id, set } => match protocol::inputs(s.program(), &set) {
            Ok(v) => {
                for (k, x) in v {
                    s.set_held(k, x);
                }
                protocol::state(s, id, None, &[])
            }
            Err(m) => protocol::error(id, "bad_input", &m),
        },
        Request::Step { id, n, set, pulse } => {
            let (set, pulse) = match (
                protocol::inputs(s.program(), &set),
                protocol::inputs(s.program(), &pulse),
            ) {
                (Ok(a), Ok(b)) => (a, b),
                (Err(m), _) | (_, Err(m)) => return protocol::error(id, "bad_input", &m),
            };
            let before: Vec<i64> = s.held().to_vec();
            for (k, x) in set {
                s.set_held(k, x);
            }
            match s.step(n.unwrap_or(1), &pulse) {
                Ok(t) => protocol::state(s, id, None, &t),
                Err(e) => {
                    for (k, x) in before.into_iter().enumerate() {
                        s.set_held(k, x);
                    }
                    fail(id, e)
                }
            }
        }
        Request::Random { id, n, seed } => match s.step_random(n.unwrap_or(1), seed.unwrap_or(0)) {
            Ok(t) => {
                let mut r = protocol::state(s, id, None, &t);
                r["note"] = json!(s.take_note());
                r
            }
            Err(e) => fail(id, e),
        },
        Request::Back { id, tick } => match s.back(tick) {
            Ok(_) => protocol::state(s, id, Some(tick), &[]),
            Err(e) => fail(id, e),
        },
        Request::Forward { id, n } => match s.forward(n.unwrap_or(1)) {
            Ok(t) => protocol::state(s, id, None, &t),
            Err(e) => fail(id, e),
        },
        Request::Reset { id } => {
            s.reset();
            protocol::state(s, id, Some(0), &[])
        }
        Request::LoadScenario { id, text } => match s.load_scenario(&text) {
            Ok(t) => protocol::state(s, id, Some(0), &t),
            Err(e) => fail(id, e),
        },
        Request::Save { id } => json!({"type": "scenario", "id": id, "text": s.scenario_text()}),
        // Started by the session loop (it streams); here only when no loop runs it.
        Request::Verify { id, .. } => protocol::error(
            id,
            "unsupported",
            "verification runs only over a WebSocket session",
        ),
    }
}

/// How to run the server.
#[derive(Clone, Debug)]
pub struct Config {
    /// The model file.
    pub path: String,
    /// The system to run (as `sim --system`).
    pub system: Option<String>,
    /// Address to bind (127.0.0.1 by default in the CLI).
    pub bind: std::net::IpAddr,
    /// Port (0: any free port).
    pub port: u16,
    /// The access token; random when `None`.
    pub token: Option<String>,
    /// Library directories for imports, searched after the importing file's directory.
    pub lib: Vec<std::path::PathBuf>,
}

/// A running server.
pub struct Handle {
    /// The address it listens on.
    pub addr: SocketAddr,
    /// The access token.
    pub token: String,
    /// The URL to open (with the token).
    pub url: String,
    shutdown: Option<tokio::sync::oneshot::Sender<()>>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Handle {
    /// Stop the server and wait for its thread.
    pub fn stop(mut self) {
        self.stop_inner();
    }

    fn stop_inner(&mut self) {
        if let Some(tx) = self.shutdown.take() {
            let _ = tx.send(());
        }
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }

    /// Wait until the server stops (it runs until the process ends).
    pub fn wait(mut self) {
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

impl Drop for Handle {
    fn drop(&mut self) {
        self.stop_inner();
    }
}

/// Why the server could not start.
#[derive(Debug)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
    /// A sentence for the user.
    pub message: String,
}

/// Kinds of [`Error`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The address could not be bound.
    Bind,
    /// The runtime could not start.
    Runtime,
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Error {}

fn random_token() -> String {
    use rand::RngExt;
    let mut rng = rand::rng();
    (0..4)
        .map(|_| format!("{:08x}", rng.random::<u32>()))
        .collect()
}

fn stamp(path: &str) -> Option<(SystemTime, u64)> {
    let m = std::fs::metadata(path).ok()?;
    Some((m.modified().ok()?, m.len()))
}

/// Start the server on its own thread: load the model (diagnostics are served, not fatal),
/// bind, watch the file. Returns once it listens.
pub fn spawn(config: Config) -> Result<Handle, Error> {
    let token = config.token.clone().unwrap_or_else(random_token);
    let rt = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .map_err(|e| Error {
            kind: ErrorKind::Runtime,
            message: format!("cannot start the runtime: {e}"),
        })?;
    let addr = SocketAddr::new(config.bind, config.port);
    // Bound here, outside any runtime, so that `spawn` may be called from async code too.
    let listener = std::net::TcpListener::bind(addr)
        .and_then(|l| l.set_nonblocking(true).map(|()| l))
        .map_err(|e| Error {
            kind: ErrorKind::Bind,
            message: format!("cannot listen on {addr}: {e}"),
        })?;
    let local = listener.local_addr().map_err(|e| Error {
        kind: ErrorKind::Bind,
        message: format!("cannot listen on {addr}: {e}"),
    })?;
    let port = local.port();
    let mut hosts = vec![
        format!("127.0.0.1:{port}"),
        format!("localhost:{port}"),
        format!("[::1]:{port}"),
    ];
    let own = if local.ip().is_ipv6() {
        format!("[{}]:{port}", local.ip())
    } else {
        format!("{}:{port}", local.ip())
    };
    if !hosts.contains(&own) {
        hosts.push(own.clone());
    }
    let shown = if local.ip().is_unspecified() {
        format!("127.0.0.1:{port}")
    } else {
        own
    };
    let url = format!("http://{shown}/?token={token}");
    let first =
        load::load_with(&config.path, config.system.as_deref(), &config.lib).map_err(Arc::new);
    let (tx, rx) = watch::channel::<Current>(first);
    let app = Arc::new(App {
        token: token.clone(),
        hosts,
        current: rx,
        sessions: AtomicU64::new(0),
        live: AtomicU64::new(0),
        parking: Parking::default(),
    });
    let (stop_tx, stop_rx) = tokio::sync::oneshot::channel::<()>();
    let cfg = config.clone();
    let thread = std::thread::Builder::new()
        .name("studio-server".into())
        .spawn(move || {
            rt.block_on(async move {
                let Ok(listener) = tokio::net::TcpListener::from_std(listener) else {
                    return;
                };
                let watcher = tokio::spawn(async move {
                    let mut last = stamp(&cfg.path);
                    loop {
                        tokio::time::sleep(WATCH_EVERY).await;
                        let now = stamp(&cfg.path);
                        if now != last {
                            last = now;
                            let (p, s) = (cfg.path.clone(), cfg.system.clone());
                            let lib = cfg.lib.clone();
                            let next = tokio::task::spawn_blocking(move || {
                                load::load_with(&p, s.as_deref(), &lib)
                            })
                            .await;
                            if let Ok(next) = next {
                                if tx.send(next.map_err(Arc::new)).is_err() {
                                    break;
                                }
                            }
                        }
                    }
                });
                let _ = axum::serve(listener, router(app))
                    .with_graceful_shutdown(async {
                        let _ = stop_rx.await;
                    })
                    .await;
                watcher.abort();
            });
        })
        .map_err(|e| Error {
            kind: ErrorKind::Runtime,
            message: format!("cannot start the server thread: {e}"),
        })?;
    Ok(Handle {
        addr: local,
        token,
        url,
        shutdown: Some(stop_tx),
        thread: Some(thread),
    })
}
