//! The WDS collision counterexample (examples/wds/collision_faulty_L.scn) loads in the studio
//! and stops where `sim` stops: examples/wds/README.md derives the collision in tick 160
//! (START in tick 1, the L-Transfer at the Storage in tick 41, the light workpiece taken in
//! tick P = 42, the heavy one available in tick A = P + 23 = 65, the Feeder in its area in
//! tick A + 95 = 160), at 160 × 1.25 s = 200 s; the run has 161 ticks.

mod common;
use common::*;
use serde_json::json;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_wds_collision_replays_in_the_studio() {
    let h = start_system(&repo("examples/wds/wds.sc"), Some("WDS:faulty_L_sensor"));
    let (mut ws, hello) = connect(&h).await;
    assert_eq!(hello["type"], "model", "{hello}");
    let scn =
        std::fs::read_to_string(repo("examples/wds/collision_faulty_L.scn")).expect("scenario");
    let l = call(&mut ws, json!({"op": "load_scenario", "text": scn})).await;
    let stop = &l["run"]["stop"];
    assert_eq!(stop["tick"], 160, "{l}");
    assert_eq!(stop["time"], json!(200.0), "{l}");
    assert!(
        stop["message"]
            .as_str()
            .is_some_and(|m| m.contains("no_collision")),
        "{stop}"
    );
    let ticks = l["ticks"].as_array().expect("ticks");
    assert_eq!(ticks.len(), 161);
    h.stop();
}
