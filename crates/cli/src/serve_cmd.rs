//! `statecheck serve`: start the validation studio (`crates/studio`) and print its URL.

use anyhow::Result;
use clap::Args;

/// Arguments of `statecheck serve`.
#[derive(Args)]
pub struct ServeArgs {
    /// The `.sc` model file (reloaded when it changes).
    model: String,
    /// The system (or chart) to run.
    #[arg(long)]
    system: Option<String>,
    /// Port to listen on (0: any free port).
    #[arg(long, default_value_t = 8080)]
    port: u16,
    /// Address to bind; anything but loopback exposes the studio to the network.
    #[arg(long, default_value = "127.0.0.1")]
    bind: std::net::IpAddr,
    /// Open the page in the default browser.
    #[arg(long)]
    open: bool,
}

/// Run the server until the process is stopped.
pub fn run(a: ServeArgs) -> Result<u8> {
    // Check the model once up front so that a broken file is reported here too; the server
    // still starts and shows the diagnostics on the page until the file is fixed.
    if let Err(e) = crate::load::load(&a.model, false) {
        if e.downcast_ref::<crate::load::ModelErrors>().is_none() {
            return Err(e);
        }
    }
    let handle = statecheck_studio::spawn(statecheck_studio::Config {
        path: a.model.clone(),
        system: a.system,
        bind: a.bind,
        port: a.port,
        token: None,
        lib: crate::load::search_path(),
    })?;
    if !a.bind.is_loopback() {
        eprintln!(
            "warning: listening on {} — reachable from other machines",
            a.bind
        );
    }
    println!("statecheck studio for {} at {}", a.model, handle.url);
    if a.open {
        let _ = std::process::Command::new("xdg-open")
            .arg(&handle.url)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn();
    }
    handle.wait();
    Ok(0)
}
