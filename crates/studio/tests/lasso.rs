//! Lasso scenarios in the studio: a `.scn` with a `loop:` line replays its ticks, reports the
//! temporal property it violates as `statecheck sim` does, and stepping past its end goes
//! around the loop until the inputs change.

mod common;
use common::*;
use serde_json::{json, Value};

/// `n` after each tick of a state reply.
fn ns(v: &Value) -> Vec<i64> {
    v["ticks"]
        .as_array()
        .expect("ticks")
        .iter()
        .map(|t| t["vars"]["c.n"].as_i64().expect("n"))
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_lasso_replays_and_steps_around_its_loop() {
    // tests/verify/temporal.sc, system Free: `reset` sets n to 0, `inc` adds 1 below 3. By
    // hand: tick 0 initialises (n = 0); tick 1 inc: n = 1; the loop is ticks 2 (reset: n = 0)
    // and 3 (inc: n = 1), so the state after tick 3 is the state after tick 1 and the run
    // n = 0, 1, (0, 1)^ω never reaches 3: `reaches3` (`F c.n == 3`, declared first) is
    // violated, reported at the last tick, 3; `gf_zero` holds (n = 0 every other tick).
    let h = start_system(&repo("tests/verify/temporal.sc"), Some("Free"));
    let (mut ws, hello) = connect(&h).await;
    assert_eq!(hello["type"], "model", "{hello}");
    let text = "-\nc.inc\nloop:\nc.reset\nc.inc\n";
    let l = call(&mut ws, json!({"op": "load_scenario", "text": text})).await;
    assert_eq!(ns(&l), [0, 1, 0, 1], "{l}");
    let lasso = &l["run"]["lasso"];
    assert_eq!(
        (lasso["start"].as_u64(), lasso["end"].as_u64()),
        (Some(2), Some(4)),
        "{l}"
    );
    assert_eq!(lasso["following"], true);
    assert!(lasso["broken"].is_null());
    assert_eq!(
        lasso["violated"]["message"],
        "property `reaches3` violated at tick 3"
    );
    // Not a stop: the run goes on around the loop.
    assert!(l["run"]["stop"].is_null());
    // Saved at its end, it is the lasso again (the loop's first tick writes every input).
    let saved = call(&mut ws, json!({"op": "save"})).await;
    let saved = saved["text"].as_str().expect("text");
    assert!(saved.contains("loop:"), "{saved}");
    // Stepping past the end: ticks 4..7 repeat the loop's inputs reset, inc, reset, inc.
    let s = step(&mut ws, 4, json!({}), json!({})).await;
    assert_eq!(ns(&s), [0, 1, 0, 1], "{s}");
    let events: Vec<Value> = s["ticks"]
        .as_array()
        .expect("ticks")
        .iter()
        .map(|t| t["events"].clone())
        .collect();
    assert_eq!(
        events,
        [
            json!(["c.reset"]),
            json!(["c.inc"]),
            json!(["c.reset"]),
            json!(["c.inc"])
        ]
    );
    // After two whole laps it is still a lasso (the loop spans ticks 2..7): saved with its
    // `loop:` line, and loaded it gives the same verdict. One tick more would not be.
    let saved = call(&mut ws, json!({"op": "save"})).await;
    let saved = saved["text"].as_str().expect("text").to_string();
    assert!(saved.contains("loop:"), "{saved}");
    let (mut ws2, _) = connect(&h).await;
    let again = call(&mut ws2, json!({"op": "load_scenario", "text": saved})).await;
    assert_eq!(ns(&again), [0, 1, 0, 1, 0, 1, 0, 1], "{again}");
    assert_eq!(
        (
            again["run"]["lasso"]["start"].as_u64(),
            again["run"]["lasso"]["violated"]["message"].as_str()
        ),
        (Some(2), Some("property `reaches3` violated at tick 7"))
    );
    // A pulse leaves the loop: inc at tick 8 (n = 2), then no events (n stays 2).
    let s = step(&mut ws, 1, json!({}), json!({"c.inc": true})).await;
    assert_eq!(ns(&s), [2], "{s}");
    assert_eq!(s["run"]["lasso"]["following"], false);
    let s = step(&mut ws, 1, json!({}), json!({})).await;
    assert_eq!(ns(&s), [2], "{s}");
    // Not a lasso any more: saved without the loop line.
    let saved = call(&mut ws, json!({"op": "save"})).await;
    assert!(!saved["text"].as_str().expect("text").contains("loop:"));
    h.stop();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_scenario_that_is_not_a_lasso_is_reported_and_not_followed() {
    // inc in the loop: n goes 1 -> 2, so the state at the loop start does not recur (the
    // scenario `sim` refuses with exit 1 in crates/cli/tests/temporal.rs).
    let h = start_system(&repo("tests/verify/temporal.sc"), Some("Free"));
    let (mut ws, _) = connect(&h).await;
    let l = call(
        &mut ws,
        json!({"op": "load_scenario", "text": "-\nc.inc\nloop:\nc.inc\n"}),
    )
    .await;
    assert_eq!(ns(&l), [0, 1, 2], "{l}");
    let lasso = &l["run"]["lasso"];
    assert!(
        lasso["broken"]
            .as_str()
            .is_some_and(|b| b.contains("not a lasso")),
        "{l}"
    );
    // Stepping uses the held inputs (no events): n stays 2.
    let s = step(&mut ws, 1, json!({}), json!({})).await;
    assert_eq!(ns(&s), [2], "{s}");
    h.stop();
}
