//! The studio follows imports like the CLI (docs/components.md): relative to the importing
//! file, then the library directories it is given; a missing import is reported on the page
//! in the importing file, and a model of composite components shows its instances by path.

mod common;
use common::*;
use statecheck_studio::load;
use std::path::PathBuf;

#[test]
fn imports_are_followed_through_the_library_path() {
    let model = repo("tests/imports/app/plant.sc");
    // `sensors.sc` is in tests/imports/lib, not beside plant.sc: without the library path it
    // is not found (E0140, at the import in plant.sc) ...
    let errs = match load::load(&model, None) {
        Ok(_) => panic!("loads without its library"),
        Err(e) => e,
    };
    assert!(
        errs.iter()
            .any(|d| d.code == "E0140" && d.file.ends_with("plant.sc") && d.line == 3),
        "{errs:?}"
    );
    // ... with it, the imported chart runs: its instance is in the page's description.
    let lib = PathBuf::from(repo("tests/imports/lib"));
    let loaded = load::load_with(&model, None, &[lib]).expect("loads with its library");
    assert!(
        loaded.model.charts.iter().any(|c| c.name == "Sensor"),
        "{:?}",
        loaded
            .model
            .charts
            .iter()
            .map(|c| &c.name)
            .collect::<Vec<_>>()
    );
}

#[test]
fn a_composite_model_shows_instances_by_path() {
    let loaded = load::load(&repo("tests/components/cell.sc"), None).expect("loads");
    assert!(
        loaded.description.contains("storage.feeder.cyl"),
        "{}",
        loaded.description
    );
}
