//! The C translation unit of a native successor generator: the program's step function as
//! `statecheck_codegen::c` generates it (with coverage counting), and `sc_expand`, which
//! unpacks one packed state, runs one tick per listed input vector and packs each successor
//! with exactly the layout of [`Packer`].

use statecheck_codegen::c::{c_type, generate_counting_covers};
use statecheck_codegen::common::slot_fields;
use statecheck_codegen::Source;
use statecheck_explicit::pack::Packer;
use statecheck_ir::Program;
use std::fmt::Write;

/// Prefix of the generated identifiers.
const PREFIX: &str = "m";

/// The whole C source of the successor generator of `program` packed by `packer`.
///
/// `sc_expand(in, vectors, idx, n, out, status, covers)`: from the packed state `in`, for
/// each `k < n`, one tick with input vector `vectors[idx[k] * N_INPUTS ..]`; `status[k]` is
/// the step's `sc_status`, and when it is `SC_OK` the successor is packed into
/// `out[k * WORDS ..]`. Coverage items hit set their byte in `covers`.
pub(crate) fn source(program: &Program, packer: &Packer) -> String {
    let files = generate_counting_covers(program, &Source::new("<checker>", ""), PREFIX);
    let fields = slot_fields(program);
    let include = format!("#include \"{}.h\"", files.prefix);
    let mut c = String::new();
    c.push_str("/* Native successor generator of statecheck's explicit engine. */\n");
    c.push_str("#include <stdint.h>\n#include <string.h>\n");
    c.push_str(&files.header);
    for line in files.source.lines().filter(|l| l.trim() != include) {
        c.push_str(line);
        c.push('\n');
    }
    let pf = &files.prefix;
    let words = packer.words;
    let n_inputs = program.inputs.len();
    let _ = writeln!(
        c,
        "\n__attribute__((visibility(\"default\")))\nvoid sc_expand(const uint64_t *in, const int64_t *vectors, const uint32_t *idx, uint32_t n,\n                uint64_t *out, int32_t *status, uint8_t *covers) {{"
    );
    let _ = writeln!(
        c,
        "    {pf}_state base;\n    memset(&base, 0, sizeof base);"
    );
    for f in packer.layout() {
        let slot = &program.slots[f.slot];
        let ty = c_type(slot);
        let name = &fields[f.slot];
        if f.width == 0 {
            let _ = writeln!(c, "    base.{name} = ({ty})(int64_t){};", lit(f.lo));
            continue;
        }
        let (w, sh) = (f.offset / 64, f.offset % 64);
        let mut bits = format!("(in[{w}] >> {sh})");
        if sh + f.width > 64 {
            bits = format!("({bits} | (in[{}] << {}))", w + 1, 64 - sh);
        }
        let _ = writeln!(
            c,
            "    base.{name} = ({ty})(int64_t)((uint64_t){} + ({bits} & {}ULL));",
            lit(f.lo),
            f.mask()
        );
    }
    let _ = writeln!(
        c,
        "    {pf}_outputs o;\n    memset(&o, 0, sizeof o);\n    o.cover_hits_ = covers;\n    {pf}_inputs i;\n    memset(&i, 0, sizeof i);"
    );
    let _ = writeln!(
        c,
        "    for (uint32_t k = 0; k < n; k++) {{\n        const int64_t *v = vectors + (uint64_t)idx[k] * {n_inputs}u;\n        (void)v;\n        {pf}_state s = base;"
    );
    for (k, inp) in program.inputs.iter().enumerate() {
        let slot = &program.slots[inp.slot as usize];
        let _ = writeln!(
            c,
            "        i.{} = ({})v[{k}];",
            fields[inp.slot as usize],
            c_type(slot)
        );
    }
    let _ = writeln!(
        c,
        "        const int st = {pf}_step(&s, &i, &o);\n        status[k] = st;\n        if (st != SC_OK) continue;\n        uint64_t *w = out + (uint64_t)k * {words}u;"
    );
    for w in 0..words {
        let _ = writeln!(c, "        w[{w}] = 0;");
    }
    for f in packer.layout().filter(|f| f.width > 0) {
        let name = &fields[f.slot];
        let (w, sh) = (f.offset / 64, f.offset % 64);
        let _ = writeln!(
            c,
            "        {{ const uint64_t x = ((uint64_t)(int64_t)s.{name} - (uint64_t){}) & {}ULL;",
            lit(f.lo),
            f.mask()
        );
        let _ = writeln!(c, "          w[{w}] |= x << {sh};");
        if sh + f.width > 64 {
            let _ = writeln!(c, "          w[{}] |= x >> {};", w + 1, 64 - sh);
        }
        c.push_str("        }\n");
    }
    c.push_str("    }\n}\n");
    c
}

/// A C literal for an `int64_t` value that is valid for every value (`INT64_MIN` has no
/// literal of its own).
fn lit(v: i64) -> String {
    if v == i64::MIN {
        "(-9223372036854775807LL - 1)".to_string()
    } else {
        format!("{v}LL")
    }
}
