//! Renderers of traces, coverage and charts. They read the IR's tick records; none of them
//! interprets the model.

pub mod coverage;
pub mod csv;
pub mod dot;
pub mod dot_text;
pub mod json;
pub mod svg;
pub mod table;
pub mod vcd;
