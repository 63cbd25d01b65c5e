//! The language server driven over in-memory channels with real LSP JSON messages, one test
//! per capability. Every expected position is counted by hand on the text below (lines and
//! columns from 0, as in LSP).

#![allow(clippy::unwrap_used)] // tests may unwrap

use lsp_server::{Connection, Message, Notification, Request, RequestId};
use serde_json::{json, Value};

/// Columns, counted by hand:
/// line 1 `  input event press;`: `press` 14..19
/// line 2 `  local n: int[0..3] = 0;`: `n` 8..9
/// line 3 `  initial Off;`: `Off` 10..13
/// line 4 `  state Off { on press -> On; }`: `Off` 8..11, `press` 17..22, `On` 26..28
/// line 5 `  state On {`: `On` 8..10
/// line 6 `    entry { n += 1; }`: `n` 12..13
/// line 7 `    on press [n < 3] -> Off;`: `press` 7..12, `n` 14..15, `Off` 24..27
const LAMP: &str = "chart Lamp {
  input event press;
  local n: int[0..3] = 0;
  initial Off;
  state Off { on press -> On; }
  state On {
    entry { n += 1; }
    on press [n < 3] -> Off;
  }
}
";

const URI: &str = "file:///work/lamp.sc";

struct Client {
    conn: Connection,
    server: Option<std::thread::JoinHandle<()>>,
    next_id: i32,
    /// publishDiagnostics notifications received, in order.
    diagnostics: Vec<Value>,
}

impl Client {
    fn start() -> Client {
        let (server, client) = Connection::memory();
        let handle = std::thread::spawn(move || {
            statecheck_lsp::run(&server).unwrap();
        });
        let mut c = Client {
            conn: client,
            server: Some(handle),
            next_id: 0,
            diagnostics: Vec::new(),
        };
        let caps = c.request("initialize", json!({ "capabilities": {} }));
        assert_eq!(
            caps["capabilities"]["textDocumentSync"],
            json!(1),
            "full sync"
        );
        c.notify("initialized", json!({}));
        c
    }

    fn notify(&self, method: &str, params: Value) {
        let n = Notification::new(method.to_string(), params);
        self.conn.sender.send(Message::Notification(n)).unwrap();
    }

    fn request(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = RequestId::from(self.next_id);
        let r = Request::new(id.clone(), method.to_string(), params);
        self.conn.sender.send(Message::Request(r)).unwrap();
        loop {
            match self.conn.receiver.recv().unwrap() {
                Message::Response(resp) if resp.id == id => {
                    assert!(resp.error.is_none(), "{method}: {:?}", resp.error);
                    return resp.result.unwrap_or(Value::Null);
                }
                Message::Notification(n) if n.method == "textDocument/publishDiagnostics" => {
                    self.diagnostics.push(n.params);
                }
                _ => {}
            }
        }
    }

    /// Wait for the next publishDiagnostics.
    fn next_diagnostics(&mut self) -> Value {
        if !self.diagnostics.is_empty() {
            return self.diagnostics.remove(0);
        }
        loop {
            if let Message::Notification(n) = self.conn.receiver.recv().unwrap() {
                if n.method == "textDocument/publishDiagnostics" {
                    return n.params;
                }
            }
        }
    }

    fn open(&mut self, text: &str) -> Value {
        self.open_uri(URI, text)
    }

    fn open_uri(&mut self, uri: &str, text: &str) -> Value {
        self.notify(
            "textDocument/didOpen",
            json!({ "textDocument": { "uri": uri, "languageId": "statecheck", "version": 1, "text": text } }),
        );
        self.next_diagnostics()
    }

    fn at(&mut self, method: &str, line: u32, character: u32, extra: Value) -> Value {
        self.at_uri(URI, method, line, character, extra)
    }

    fn at_uri(
        &mut self,
        uri: &str,
        method: &str,
        line: u32,
        character: u32,
        extra: Value,
    ) -> Value {
        let mut params = json!({
            "textDocument": { "uri": uri },
            "position": { "line": line, "character": character }
        });
        if let (Some(p), Some(e)) = (params.as_object_mut(), extra.as_object()) {
            for (k, v) in e {
                p.insert(k.clone(), v.clone());
            }
        }
        self.request(method, params)
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        let _ = self.request("shutdown", Value::Null);
        self.notify("exit", Value::Null);
        if let Some(h) = self.server.take() {
            h.join().unwrap();
        }
    }
}

fn range(l0: u32, c0: u32, l1: u32, c1: u32) -> Value {
    json!({ "start": { "line": l0, "character": c0 }, "end": { "line": l1, "character": c1 } })
}

#[test]
fn diagnostics_as_you_type() {
    let mut c = Client::start();
    // `chart C { initial A; state A { on [x ` is 37 characters: the `=` is at 37..38.
    let bad = "chart C { initial A; state A { on [x = 1] -> A; } }\n";
    let d = c.open(bad);
    assert_eq!(d["uri"], json!(URI));
    let diags = d["diagnostics"].as_array().unwrap();
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0]["code"], json!("E0015"));
    assert_eq!(diags[0]["severity"], json!(1));
    assert_eq!(diags[0]["range"], range(0, 37, 0, 38));
    // Fixed by the next keystroke: the comparison is right, `x` is now unknown (E0101 at
    // 35..36), then declared: no diagnostics.
    c.notify(
        "textDocument/didChange",
        json!({ "textDocument": { "uri": URI, "version": 2 },
                "contentChanges": [{ "text": "chart C { initial A; state A { on [x == 1] -> A; } }\n" }] }),
    );
    let d = c.next_diagnostics();
    let diags = d["diagnostics"].as_array().unwrap();
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0]["code"], json!("E0101"));
    assert_eq!(diags[0]["range"], range(0, 35, 0, 36));
    c.notify(
        "textDocument/didChange",
        json!({ "textDocument": { "uri": URI, "version": 3 },
                "contentChanges": [{ "text": "chart C { input x: int[0..1]; initial A; state A { on [x == 1] -> A; } }\n" }] }),
    );
    let d = c.next_diagnostics();
    assert_eq!(d["diagnostics"], json!([]));
}

#[test]
fn hover_shows_the_declaration_with_type_and_range() {
    let mut c = Client::start();
    c.open(LAMP);
    let h = c.at("textDocument/hover", 7, 14, json!({}));
    assert_eq!(h["range"], range(7, 14, 7, 15));
    let text = h["contents"]["value"].as_str().unwrap();
    assert!(text.contains("local variable `n`"), "{text}");
    assert!(text.contains("local n: int[0..3] = 0"), "{text}");
    let h = c.at("textDocument/hover", 4, 18, json!({}));
    assert_eq!(h["range"], range(4, 17, 4, 22));
    assert!(h["contents"]["value"]
        .as_str()
        .unwrap()
        .contains("input event press"));
}

#[test]
fn go_to_definition() {
    let mut c = Client::start();
    c.open(LAMP);
    // `Off` in `-> Off` (line 7) is declared at line 4, 8..11.
    let d = c.at("textDocument/definition", 7, 25, json!({}));
    assert_eq!(d["uri"], json!(URI));
    assert_eq!(d["range"], range(4, 8, 4, 11));
    // `On` in `-> On` (line 4) at line 5, 8..10.
    let d = c.at("textDocument/definition", 4, 27, json!({}));
    assert_eq!(d["range"], range(5, 8, 5, 10));
}

/// A document that imports a chart: no "unknown chart" diagnostic, and go-to-definition on
/// the imported name opens the library file (tests/components/dead_imported.sc imports
/// lib/latch.sc, whose line 1 is `chart Latch {`: `Latch` at 6..11).
#[test]
fn imports_are_followed() {
    let root = std::fs::canonicalize(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).unwrap();
    let path = root.join("tests/components/dead_imported.sc");
    let text = std::fs::read_to_string(&path).unwrap();
    let uri = format!("file://{}", path.display());
    let mut c = Client::start();
    let d = c.open_uri(&uri, &text);
    assert_eq!(d["diagnostics"], json!([]), "{d}");
    // Line 5 is `  instance l: Latch;`: `Latch` at 14..19.
    let def = c.at_uri(&uri, "textDocument/definition", 5, 16, json!({}));
    let lib = root.join("tests/components/lib/latch.sc");
    assert_eq!(
        def["uri"],
        json!(format!("file://{}", lib.display())),
        "{def}"
    );
    assert_eq!(def["range"], range(1, 6, 1, 11));
}

/// Find references and rename across imports: `Latch` is declared in lib/latch.sc (line 1,
/// `chart Latch {`: 6..11) and used in tests/components/dead_imported.sc (line 5,
/// `  instance l: Latch;`: 14..19); both files are found from either occurrence.
#[test]
fn references_and_rename_follow_imports() {
    let root = std::fs::canonicalize(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).unwrap();
    let path = root.join("tests/components/dead_imported.sc");
    let text = std::fs::read_to_string(&path).unwrap();
    let uri = format!("file://{}", path.display());
    let lib = format!(
        "file://{}",
        root.join("tests/components/lib/latch.sc").display()
    );
    let mut c = Client::start();
    c.open_uri(&uri, &text);
    let r = c.at_uri(
        &uri,
        "textDocument/references",
        5,
        16,
        json!({ "context": { "includeDeclaration": true } }),
    );
    let found: Vec<(&Value, &Value)> = r
        .as_array()
        .unwrap()
        .iter()
        .map(|l| (&l["uri"], &l["range"]))
        .collect();
    assert_eq!(
        found,
        vec![
            (&json!(uri), &range(5, 14, 5, 19)),
            (&json!(lib), &range(1, 6, 1, 11))
        ],
        "{r}"
    );
    let r = c.at_uri(
        &uri,
        "textDocument/references",
        5,
        16,
        json!({ "context": { "includeDeclaration": false } }),
    );
    assert_eq!(r.as_array().unwrap().len(), 1, "{r}");
    let e = c.at_uri(
        &uri,
        "textDocument/rename",
        5,
        16,
        json!({ "newName": "Flag" }),
    );
    assert_eq!(e["changes"][&uri][0]["range"], range(5, 14, 5, 19), "{e}");
    assert_eq!(e["changes"][&lib][0]["range"], range(1, 6, 1, 11), "{e}");
    assert_eq!(e["changes"][&lib][0]["newText"], json!("Flag"), "{e}");
}

#[test]
fn find_references() {
    let mut c = Client::start();
    c.open(LAMP);
    let r = c.at(
        "textDocument/references",
        1,
        15,
        json!({ "context": { "includeDeclaration": true } }),
    );
    let ranges: Vec<&Value> = r.as_array().unwrap().iter().map(|l| &l["range"]).collect();
    assert_eq!(
        ranges,
        vec![
            &range(1, 14, 1, 19),
            &range(4, 17, 4, 22),
            &range(7, 7, 7, 12)
        ]
    );
    let r = c.at(
        "textDocument/references",
        1,
        15,
        json!({ "context": { "includeDeclaration": false } }),
    );
    assert_eq!(r.as_array().unwrap().len(), 2);
}

#[test]
fn rename_every_occurrence() {
    let mut c = Client::start();
    c.open(LAMP);
    let e = c.at("textDocument/rename", 6, 12, json!({ "newName": "count" }));
    let edits = e["changes"][URI].as_array().unwrap();
    let ranges: Vec<&Value> = edits.iter().map(|t| &t["range"]).collect();
    // `n += 1` counts once: the desugared `n + 1` repeats the target's span.
    assert_eq!(
        ranges,
        vec![
            &range(2, 8, 2, 9),
            &range(6, 12, 6, 13),
            &range(7, 14, 7, 15)
        ]
    );
    assert!(edits.iter().all(|t| t["newText"] == json!("count")));
    // Not an identifier: no edit.
    let e = c.at("textDocument/rename", 6, 12, json!({ "newName": "1x" }));
    assert_eq!(e, Value::Null);
}

#[test]
fn completion_of_states_events_and_variables() {
    let mut c = Client::start();
    c.open(LAMP);
    let r = c.at("textDocument/completion", 7, 4, json!({}));
    let items = r.as_array().unwrap();
    let find = |l: &str| items.iter().find(|i| i["label"] == json!(l)).unwrap()["kind"].clone();
    assert_eq!(find("press"), json!(23)); // EVENT
    assert_eq!(find("n"), json!(6)); // VARIABLE
    assert_eq!(find("Off"), json!(7)); // CLASS: a state
    assert_eq!(find("On"), json!(7));
    assert_eq!(items.len(), 4, "{items:?}");
}

#[test]
fn document_symbols_outline_the_state_hierarchy() {
    let mut c = Client::start();
    c.open(LAMP);
    let r = c.request(
        "textDocument/documentSymbol",
        json!({ "textDocument": { "uri": URI } }),
    );
    let top = r.as_array().unwrap();
    assert_eq!(top.len(), 1);
    assert_eq!(top[0]["name"], json!("Lamp"));
    assert_eq!(top[0]["range"], range(0, 0, 9, 1));
    assert_eq!(top[0]["selectionRange"], range(0, 6, 0, 10));
    let names: Vec<&Value> = top[0]["children"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| &s["name"])
        .collect();
    assert_eq!(names, vec!["press", "n", "Off", "On"]);
    let on = &top[0]["children"][3];
    assert_eq!(on["range"], range(5, 2, 8, 3));
    assert_eq!(on["selectionRange"], range(5, 8, 5, 10));
}

#[test]
fn formatting_uses_the_formatter() {
    let mut c = Client::start();
    c.open("chart C{initial A;state A;}");
    let r = c.request(
        "textDocument/formatting",
        json!({ "textDocument": { "uri": URI }, "options": { "tabSize": 2, "insertSpaces": true } }),
    );
    let edits = r.as_array().unwrap();
    assert_eq!(edits.len(), 1);
    assert_eq!(edits[0]["range"], range(0, 0, 0, 27));
    assert_eq!(
        edits[0]["newText"],
        json!("chart C {\n  initial A;\n  state A;\n}\n")
    );
}

#[test]
fn code_action_fixes_a_diagnostic_with_a_suggestion() {
    let mut c = Client::start();
    c.open("chart C { initial A; state A { on [x = 1] -> A; } }\n");
    let r = c.request(
        "textDocument/codeAction",
        json!({ "textDocument": { "uri": URI }, "range": range(0, 37, 0, 38),
                "context": { "diagnostics": [] } }),
    );
    let actions = r.as_array().unwrap();
    assert_eq!(actions.len(), 1, "{actions:?}");
    assert_eq!(actions[0]["kind"], json!("quickfix"));
    let edit = &actions[0]["edit"]["changes"][URI][0];
    assert_eq!(edit["range"], range(0, 37, 0, 38));
    assert_eq!(edit["newText"], json!("=="));
}
