//! The page, embedded in the binary: hand-written HTML, CSS and JavaScript, and the vendored
//! layout library (elkjs, EPL-2.0; `crates/studio/assets/vendor/`, refreshed by
//! `crates/studio/assets/vendor/refresh.sh` at a pinned version with checksums).

/// The page.
pub const INDEX: &str = include_str!("../assets/index.html");

/// Content type and body of a static asset.
pub fn get(name: &str) -> (&'static str, &'static str) {
    match name {
        "app.js" => (
            "text/javascript; charset=utf-8",
            include_str!("../assets/app.js"),
        ),
        "chart.js" => (
            "text/javascript; charset=utf-8",
            include_str!("../assets/chart.js"),
        ),
        "wave.js" => (
            "text/javascript; charset=utf-8",
            include_str!("../assets/wave.js"),
        ),
        "layout-worker.js" => (
            "text/javascript; charset=utf-8",
            include_str!("../assets/layout-worker.js"),
        ),
        "style.css" => (
            "text/css; charset=utf-8",
            include_str!("../assets/style.css"),
        ),
        "elk.js" => (
            "text/javascript; charset=utf-8",
            include_str!("../assets/vendor/elk.bundled.js"),
        ),
        _ => ("text/plain", ""),
    }
}
