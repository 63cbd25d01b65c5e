//! `statecheck lsp` over real stdio with Content-Length framing: initialize, open a document,
//! receive its diagnostics, shut down, exit 0. (Each capability is tested in
//! `crates/lsp/tests/server.rs`.)

#![allow(clippy::unwrap_used)] // tests may unwrap

use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

fn frame(v: &str) -> String {
    format!("Content-Length: {}\r\n\r\n{v}", v.len())
}

fn read_message(r: &mut impl BufRead) -> String {
    let mut len = 0;
    loop {
        let mut line = String::new();
        r.read_line(&mut line).unwrap();
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some(n) = line.strip_prefix("Content-Length: ") {
            len = n.parse().unwrap();
        }
    }
    let mut buf = vec![0; len];
    r.read_exact(&mut buf).unwrap();
    String::from_utf8(buf).unwrap()
}

#[test]
fn lsp_over_stdio_publishes_diagnostics_and_exits_cleanly() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .arg("lsp")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let mut out = BufReader::new(child.stdout.take().unwrap());
    stdin
        .write_all(
            frame(r#"{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{}}}"#)
                .as_bytes(),
        )
        .unwrap();
    let init = read_message(&mut out);
    assert!(
        init.contains(r#""id":1"#) && init.contains("hoverProvider"),
        "{init}"
    );
    stdin
        .write_all(frame(r#"{"jsonrpc":"2.0","method":"initialized","params":{}}"#).as_bytes())
        .unwrap();
    // `chart C { state A; }` has no `initial`: E0106.
    let open = r#"{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"file:///m.sc","languageId":"statecheck","version":1,"text":"chart C { state A; }"}}}"#;
    stdin.write_all(frame(open).as_bytes()).unwrap();
    let diags = read_message(&mut out);
    assert!(diags.contains("publishDiagnostics"), "{diags}");
    assert!(diags.contains("E0106"), "{diags}");
    stdin
        .write_all(frame(r#"{"jsonrpc":"2.0","id":2,"method":"shutdown"}"#).as_bytes())
        .unwrap();
    let bye = read_message(&mut out);
    assert!(bye.contains(r#""id":2"#), "{bye}");
    stdin
        .write_all(frame(r#"{"jsonrpc":"2.0","method":"exit"}"#).as_bytes())
        .unwrap();
    drop(stdin);
    assert_eq!(child.wait().unwrap().code(), Some(0));
}
