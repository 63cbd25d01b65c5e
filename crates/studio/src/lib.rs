//! The validation studio behind `statecheck serve`: a loopback web server whose page draws
//! every instance's chart, animates it tick by tick, lets a person be the environment, plots
//! signals and replays scenarios (counterexamples of `statecheck verify --cex-dir` included).
//!
//! It exists so that a designer can *see* the machine run. It adds no semantics: the model is
//! read as `statecheck sim` reads it ([`load`]) and every tick is
//! [`statecheck_sim::tick_once`] on the IR's `Machine` ([`session`]). The page is static and
//! embedded ([`assets`]); it talks to the server over one WebSocket per session
//! ([`protocol`], [`server`]).

pub mod assets;
pub mod describe;
pub mod load;
pub mod park;
pub mod protocol;
pub mod server;
pub mod session;
pub mod verify;

pub use server::{spawn, Config, Error, ErrorKind, Handle};
