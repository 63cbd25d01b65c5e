//! A session survives a browser reload (resumed by its key) and a change of the model file
//! (its inputs re-applied when they still apply, kept through a file that does not check).

mod common;
use common::*;
use serde_json::{json, Value};

/// The one-chart counter of the protocol tests, adding `inc` per tick with `go`. By hand: tick
/// 0 enters A (no `during` in the entering tick), so with `go` held from the start n is 0,
/// inc, 2·inc after ticks 0, 1, 2.
fn counter(inc: u32) -> String {
    format!("chart C {{\n  input go: bool = false;\n  output n: int[0..9] = 0;\n  initial A;\n  state A {{ during {{ if go {{ n = min(9, n + {inc}); }} }} }}\n}}\n")
}

fn ns(v: &Value) -> Vec<i64> {
    v["ticks"]
        .as_array()
        .expect("ticks")
        .iter()
        .map(|t| t["vars"]["C.n"].as_i64().expect("n"))
        .collect()
}

/// Connect presenting a resume key; returns the hello and the first state message.
async fn reconnect(h: &statecheck_studio::Handle, key: &str) -> (Ws, Value, Value) {
    let (mut ws, ()) = connect_with(
        h,
        &format!("{TOKEN}&resume={key}"),
        Some(&format!("http://127.0.0.1:{}", h.addr.port())),
        None,
    )
    .await
    .expect("connects");
    let hello = next(&mut ws).await;
    let st = next(&mut ws).await;
    (ws, hello, st)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_reload_resumes_the_session_and_a_changed_model_reapplies_its_inputs() {
    let dir = std::env::temp_dir().join(format!("studio-resume-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let model = dir.join("m.sc");
    std::fs::write(&model, counter(1)).expect("write");
    let h = start(model.to_str().expect("path"));
    let (mut ws, hello) = connect(&h).await;
    let key = hello["resume"].as_str().expect("a resume key").to_string();
    assert_eq!(key.len(), 32);
    let s = step(&mut ws, 3, json!({"C.go": true}), json!({})).await;
    assert_eq!(ns(&s), [0, 1, 2]);
    drop(ws);
    // The reload: same key, the three ticks again, `go` still held.
    let mut resumed = None;
    for _ in 0..50 {
        // (the server parks the session when it sees the socket close)
        tokio::time::sleep(std::time::Duration::from_millis(20)).await;
        let (ws, hello, st) = reconnect(&h, &key).await;
        if st["run"]["ticks"] == 3 {
            assert_eq!(hello["resume"], key.as_str());
            resumed = Some((ws, st));
            break;
        }
    }
    let (mut ws, st) = resumed.expect("the session resumed");
    assert_eq!(ns(&st), [0, 1, 2], "{st}");
    assert_eq!(st["held"]["C.go"], true);
    // An unknown key: a new session, a new key.
    let (_, hello2, st2) = reconnect(&h, "0123456789abcdef0123456789abcdef").await;
    assert_eq!(st2["run"]["ticks"], 0);
    assert_ne!(hello2["resume"], "0123456789abcdef0123456789abcdef");
    // The file changes to add 2 per tick: the same inputs give n = 0, 2, 4.
    std::fs::write(&model, counter(2)).expect("write");
    let m = next(&mut ws).await;
    assert_eq!(m["type"], "model", "{m}");
    assert_eq!(m["resume"], key.as_str());
    let st = next(&mut ws).await;
    assert_eq!(ns(&st), [0, 2, 4], "{st}");
    // A file that does not check keeps the session aside; fixed, the inputs apply again
    // (3 per tick: 0, 3, 6).
    std::fs::write(&model, counter(3).replace("initial A;", "initial Nowhere;")).expect("write");
    assert_eq!(next(&mut ws).await["type"], "diagnostics");
    std::fs::write(&model, counter(3)).expect("write");
    assert_eq!(next(&mut ws).await["type"], "model");
    let st = next(&mut ws).await;
    assert_eq!(ns(&st), [0, 3, 6], "{st}");
    // Without the input `go` the inputs do not apply: the run starts again, and says why.
    std::fs::write(
        &model,
        "chart C {\n  output n: int[0..9] = 0;\n  initial A;\n  state A { }\n}\n",
    )
    .expect("write");
    assert_eq!(next(&mut ws).await["type"], "model");
    let st = next(&mut ws).await;
    assert_eq!(st["run"]["ticks"], 0, "{st}");
    assert!(
        st["note"]
            .as_str()
            .is_some_and(|n| n.contains("do not apply")),
        "{st}"
    );
    h.stop();
    let _ = std::fs::remove_dir_all(&dir);
}
