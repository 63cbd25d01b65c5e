//! Test helpers: start a studio on loopback, talk to it over a WebSocket.
#![allow(dead_code)] // reason: each test binary uses a different subset of the helpers

use futures_util::{SinkExt, StreamExt};
use serde_json::{json, Value};
use statecheck_studio::{spawn, Config, Handle};
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::tungstenite::Message;

/// A client WebSocket.
pub type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

/// The token the test servers use.
pub const TOKEN: &str = "test-token-0123";

/// A file of the repository.
pub fn repo(path: &str) -> String {
    format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))
}

/// A studio for `model` on 127.0.0.1, any free port.
pub fn start(model: &str) -> Handle {
    start_system(model, None)
}

/// A studio for one system of `model`.
pub fn start_system(model: &str, system: Option<&str>) -> Handle {
    spawn(Config {
        path: model.to_string(),
        system: system.map(str::to_string),
        bind: "127.0.0.1".parse().expect("address"),
        port: 0,
        token: Some(TOKEN.into()),
        lib: Vec::new(),
    })
    .expect("server starts")
}

/// Connect with the right token and origin; returns the socket after the hello (the model
/// message) and the initial state message.
pub async fn connect(h: &Handle) -> (Ws, Value) {
    let (mut ws, _) = connect_with(
        h,
        TOKEN,
        Some(&format!("http://127.0.0.1:{}", h.addr.port())),
        None,
    )
    .await
    .expect("connects");
    let hello = next(&mut ws).await;
    if hello["type"] == "model" {
        let st = next(&mut ws).await;
        assert_eq!(st["type"], "state");
    }
    (ws, hello)
}

/// Connect with a chosen token, Origin and Host.
pub async fn connect_with(
    h: &Handle,
    token: &str,
    origin: Option<&str>,
    host: Option<&str>,
) -> Result<(Ws, ()), tokio_tungstenite::tungstenite::Error> {
    let url = format!("ws://127.0.0.1:{}/ws?token={token}", h.addr.port());
    let mut req = url.into_client_request()?;
    if let Some(o) = origin {
        req.headers_mut()
            .insert("Origin", o.parse().expect("header"));
    }
    if let Some(x) = host {
        req.headers_mut().insert("Host", x.parse().expect("header"));
    }
    let (ws, _) = tokio_tungstenite::connect_async_with_config(
        req,
        Some(
            tokio_tungstenite::tungstenite::protocol::WebSocketConfig::default()
                .max_message_size(Some(64 << 20)),
        ),
        false,
    )
    .await?;
    Ok((ws, ()))
}

/// The next text message as JSON.
pub async fn next(ws: &mut Ws) -> Value {
    loop {
        let m = tokio::time::timeout(std::time::Duration::from_secs(60), ws.next())
            .await
            .expect("a reply within 60 s")
            .expect("socket open")
            .expect("no socket error");
        if let Message::Text(t) = m {
            return serde_json::from_str(t.as_str()).expect("JSON reply");
        }
    }
}

/// Send a request and wait for its reply.
pub async fn call(ws: &mut Ws, req: Value) -> Value {
    ws.send(Message::text(req.to_string())).await.expect("send");
    next(ws).await
}

/// Step `n` ticks with `set` and `pulse`.
pub async fn step(ws: &mut Ws, n: u64, set: Value, pulse: Value) -> Value {
    call(
        ws,
        json!({"op": "step", "n": n, "set": set, "pulse": pulse}),
    )
    .await
}
