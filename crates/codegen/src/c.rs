//! C99 code generation: a header and a source file per system.
//!
//! The header declares the state, input and output structs (fixed-width fields chosen from
//! each slot's range), enums naming the values of enumerated slots (active-state selectors
//! name their states), and `PREFIX_init`, `PREFIX_step` and `PREFIX_slots`. The source holds
//! one static function per shared entry/exit procedure and the step function, translated
//! statement by statement from the IR. No heap, no recursion, no floating point; run-time
//! errors return an [`sc_status`](RUNTIME) code and record the failing site in the outputs.

use crate::c_expr::{lets_in_stmts, lit, CEmit};
use crate::common::{area, ident, int_width, slot_fields, Area, Source};
use statecheck_ir::{Program, Slot, SlotId, ValueKind};
use std::collections::BTreeSet;
use std::fmt::Write;

/// Generated C files of one system.
#[derive(Clone, Debug)]
pub struct CFiles {
    /// Base name of the files (`PREFIX.h`, `PREFIX.c`, `PREFIX_harness.c`).
    pub prefix: String,
    /// The header.
    pub header: String,
    /// The source.
    pub source: String,
}

/// Checked arithmetic shared by every generated program (guarded, so several programs can be
/// compiled into one translation unit). Mirrors `statecheck_model::ops` exactly.
pub const RUNTIME: &str = r#"#ifndef STATECHECK_RUNTIME
#define STATECHECK_RUNTIME
/* Status of a step: SC_OK, or the run-time error that stopped it (docs/semantics.md, R9). */
typedef enum {
    SC_OK = 0,
    SC_ERR_RANGE = 1,
    SC_ERR_DIVISION_BY_ZERO = 2,
    SC_ERR_BAD_SHIFT = 3,
    SC_ERR_OVERFLOW = 4
} sc_status;
/* A slot's value as int64_t (a call, so that range warnings do not see the storage type). */
static inline int64_t sc_v(int64_t x) { return x; }
static inline int64_t sc_min(int64_t a, int64_t b) { return a < b ? a : b; }
static inline int64_t sc_max(int64_t a, int64_t b) { return a > b ? a : b; }
static inline int sc_add(int64_t a, int64_t b, int64_t *r) {
    if ((b > 0 && a > INT64_MAX - b) || (b < 0 && a < INT64_MIN - b)) return SC_ERR_OVERFLOW;
    *r = a + b;
    return SC_OK;
}
static inline int sc_sub(int64_t a, int64_t b, int64_t *r) {
    if ((b < 0 && a > INT64_MAX + b) || (b > 0 && a < INT64_MIN + b)) return SC_ERR_OVERFLOW;
    *r = a - b;
    return SC_OK;
}
static inline int sc_mul(int64_t a, int64_t b, int64_t *r) {
    if (a > 0) {
        if (b > 0) { if (a > INT64_MAX / b) return SC_ERR_OVERFLOW; }
        else if (b < INT64_MIN / a) return SC_ERR_OVERFLOW;
    } else if (b > 0) {
        if (a < INT64_MIN / b) return SC_ERR_OVERFLOW;
    } else if (a != 0 && b < INT64_MAX / a) return SC_ERR_OVERFLOW;
    *r = a * b;
    return SC_OK;
}
static inline int sc_div(int64_t a, int64_t b, int64_t *r) {
    if (b == 0) return SC_ERR_DIVISION_BY_ZERO;
    if (a == INT64_MIN && b == -1) return SC_ERR_OVERFLOW;
    *r = a / b;
    return SC_OK;
}
static inline int sc_rem(int64_t a, int64_t b, int64_t *r) {
    if (b == 0) return SC_ERR_DIVISION_BY_ZERO;
    if (a == INT64_MIN && b == -1) return SC_ERR_OVERFLOW;
    *r = a % b;
    return SC_OK;
}
/* Arithmetic right shift without implementation-defined behaviour; 0 <= b <= 62. */
static inline int64_t sc_shr_ok(int64_t a, int64_t b) { return a < 0 ? ~(~a >> b) : a >> b; }
static inline int sc_shr(int64_t a, int64_t b, int64_t *r) {
    if (b < 0 || b > 62) return SC_ERR_BAD_SHIFT;
    *r = sc_shr_ok(a, b);
    return SC_OK;
}
static inline int sc_shl(int64_t a, int64_t b, int64_t *r) {
    if (b < 0 || b > 62) return SC_ERR_BAD_SHIFT;
    return sc_mul(a, (int64_t)1 << b, r);
}
#endif
"#;

/// The C storage type of a slot.
pub fn c_type(s: &Slot) -> &'static str {
    match int_width(s.lo, s.hi) {
        (false, 8) => "uint8_t",
        (false, 16) => "uint16_t",
        (false, 32) => "uint32_t",
        (true, 8) => "int8_t",
        (true, 16) => "int16_t",
        (true, 32) => "int32_t",
        _ => "int64_t",
    }
}

/// Everything the C emitters need to name things.
pub(crate) struct Names {
    /// Lower-case prefix of functions and types.
    pub prefix: String,
    /// Field name of each slot.
    pub fields: Vec<String>,
    /// Function name of each procedure.
    pub procs: Vec<String>,
    /// Value names of each slot, where known.
    pub values: Vec<Option<Vec<String>>>,
    /// Record coverage hits through `o->cover_hits_` (see [`generate_counting_covers`]).
    pub count_covers: bool,
}

impl Names {
    pub(crate) fn new(p: &Program, prefix: &str) -> Names {
        let mut seen = BTreeSet::new();
        let procs = p
            .procs
            .iter()
            .enumerate()
            .map(|(k, pr)| {
                let mut n = format!("{prefix}_{}", ident(&pr.name));
                if !seen.insert(n.clone()) {
                    n = format!("{n}_{k}");
                }
                n
            })
            .collect();
        Names {
            prefix: prefix.to_string(),
            fields: slot_fields(p),
            procs,
            values: p
                .slots
                .iter()
                .map(|s| match &s.display {
                    ValueKind::Enum(n) => Some(n.clone()),
                    _ => None,
                })
                .collect(),
            count_covers: false,
        }
    }

    /// Upper-case name of an enum literal of a slot.
    pub(crate) fn literal(&self, slot: SlotId, name: &str) -> String {
        format!(
            "{}_{}_{}",
            self.prefix,
            self.fields[slot as usize],
            ident(name)
        )
        .to_uppercase()
    }
}

/// [`generate`], for a model checker that runs the step function itself: the outputs struct
/// gains `uint8_t *cover_hits_`, and every coverage item of the program sets
/// `o->cover_hits_[id] = 1` when it is hit (the caller points it at one byte per item of
/// [`Program::covers`]); the step function is `static inline` (GCC's `always_inline`), to be
/// compiled in one translation unit with the checker's driver. Everything else is exactly
/// the code of [`generate`].
pub fn generate_counting_covers(p: &Program, src: &Source, prefix: &str) -> CFiles {
    let prefix = ident(prefix).to_lowercase();
    let mut n = Names::new(p, &prefix);
    n.count_covers = true;
    CFiles {
        header: header(p, src, &n),
        source: source(p, src, &n),
        prefix,
    }
}

/// Generate the C header and source of `p` with identifiers prefixed by `prefix`.
pub fn generate(p: &Program, src: &Source, prefix: &str) -> CFiles {
    generate_named(p, src, prefix, None)
}

/// [`generate`], with the value names of slots (see `statecheck_ir::view::value_names`) so that
/// active-state selectors get enums naming their states.
pub fn generate_named(
    p: &Program,
    src: &Source,
    prefix: &str,
    values: Option<Vec<Option<Vec<String>>>>,
) -> CFiles {
    let prefix = ident(prefix).to_lowercase();
    let mut n = Names::new(p, &prefix);
    if let Some(v) = values.filter(|v| v.len() == p.slots.len()) {
        n.values = v;
    }
    CFiles {
        header: header(p, src, &n),
        source: source(p, src, &n),
        prefix,
    }
}

fn header(p: &Program, src: &Source, n: &Names) -> String {
    let pf = &n.prefix;
    let guard = format!("{}_H", pf.to_uppercase());
    let mut h = String::new();
    let _ = writeln!(
        h,
        "/* Generated by statecheck from {} (system `{}`). Do not edit. */",
        src.file, p.name
    );
    let _ = writeln!(
        h,
        "#ifndef {guard}\n#define {guard}\n\n#include <stdint.h>\n"
    );
    h.push_str(RUNTIME);
    h.push('\n');
    for (k, s) in p.slots.iter().enumerate() {
        if let Some(names) = &n.values[k] {
            let _ = writeln!(h, "/* Values of `{}`. */\ntypedef enum {{", s.name);
            for (v, name) in names.iter().enumerate() {
                let _ = writeln!(h, "    {} = {v},", n.literal(k as u32, name));
            }
            let _ = writeln!(h, "}} {pf}_{}_t;\n", n.fields[k]);
        }
    }
    let areas = [
        (
            Area::State,
            "state",
            "Persistent state: what a checker stores.",
        ),
        (Area::Input, "inputs", "Free inputs of one tick."),
        (
            Area::Temp,
            "outputs",
            "Temporaries of the last tick (present events, ...) and the error report.",
        ),
    ];
    for (ar, name, doc) in areas {
        let _ = writeln!(h, "/* {doc} */\ntypedef struct {{");
        let mut any = false;
        for (k, s) in p.slots.iter().enumerate() {
            if area(p, k as u32) != ar {
                continue;
            }
            any = true;
            let _ = writeln!(
                h,
                "    {} {}; /* {} in {}..{} */",
                c_type(s),
                n.fields[k],
                s.name,
                s.lo,
                s.hi
            );
        }
        if ar == Area::Temp {
            h.push_str("    uint32_t error_site; /* site of the run-time error */\n");
            h.push_str("    int64_t error_value, error_lo, error_hi; /* range errors */\n");
            if n.count_covers {
                h.push_str("    uint8_t *cover_hits_; /* one byte per coverage item */\n");
            }
        } else if !any {
            h.push_str("    uint8_t unused_;\n");
        }
        let _ = writeln!(h, "}} {pf}_{name};\n");
    }
    let _ = writeln!(
        h,
        "/* Number of slots written by {pf}_slots. */\n#define {}_N_SLOTS {}\n",
        pf.to_uppercase(),
        p.slots.len()
    );
    let _ = writeln!(
        h,
        "/* Every slot at its initial value (before tick 0). */\nvoid {pf}_init({pf}_state *s, {pf}_inputs *i, {pf}_outputs *o);"
    );
    let _ = writeln!(
        h,
        "/* One tick; returns SC_OK or the run-time error that stopped it (o->error_site). */\n{}int {pf}_step({pf}_state *s, const {pf}_inputs *in, {pf}_outputs *o);",
        step_storage(n)
    );
    let _ = writeln!(
        h,
        "/* All slot values in IR order (state, inputs, temporaries). */\nvoid {pf}_slots(const {pf}_state *s, const {pf}_inputs *i, const {pf}_outputs *o, int64_t *v);"
    );
    let _ = writeln!(h, "\n#endif");
    h
}

/// Storage class of the step function: inlined into the checker's driver, which is compiled
/// in the same translation unit (see [`generate_counting_covers`]).
fn step_storage(n: &Names) -> &'static str {
    if n.count_covers {
        "static inline __attribute__((always_inline)) "
    } else {
        ""
    }
}

fn slot_ref(p: &Program, n: &Names, s: SlotId) -> String {
    let f = &n.fields[s as usize];
    match area(p, s) {
        Area::State => format!("s->{f}"),
        Area::Input => format!("i->{f}"),
        Area::Temp => format!("o->{f}"),
    }
}

fn case_label(n: &Names, s: SlotId, k: usize) -> String {
    match &n.values[s as usize] {
        Some(names) if k < names.len() => n.literal(s, &names[k]),
        _ => k.to_string(),
    }
}

fn source(p: &Program, src: &Source, n: &Names) -> String {
    let pf = &n.prefix;
    let mut c = String::new();
    let _ = writeln!(
        c,
        "/* Generated by statecheck from {} (system `{}`). Do not edit. */\n#include \"{pf}.h\"\n",
        src.file, p.name
    );
    let _ = writeln!(
        c,
        "static inline int {pf}_fail({pf}_outputs *o, int status, uint32_t site, int64_t value, int64_t lo, int64_t hi) {{\n    o->error_site = site;\n    o->error_value = value;\n    o->error_lo = lo;\n    o->error_hi = hi;\n    return status;\n}}\n"
    );
    let sig =
        |name: &str| format!("static int {name}({pf}_state *s, {pf}_inputs *i, {pf}_outputs *o)");
    for name in &n.procs {
        let _ = writeln!(c, "{};", sig(name));
    }
    c.push('\n');
    for (k, pr) in p.procs.iter().enumerate() {
        let _ = writeln!(c, "/* {} */\n{} {{", pr.name, sig(&n.procs[k]));
        c.push_str("    (void)s;\n    (void)i;\n    (void)o;\n");
        c.push_str(&body(p, src, n, &pr.body));
        c.push_str("    return SC_OK;\n}\n\n");
    }
    let _ = writeln!(
        c,
        "{}int {pf}_step({pf}_state *s, const {pf}_inputs *in, {pf}_outputs *o) {{\n    {pf}_inputs i_ = *in;\n    {pf}_inputs *i = &i_;\n    (void)i;",
        step_storage(n)
    );
    c.push_str(&body(p, src, n, &p.step));
    c.push_str("    return SC_OK;\n}\n\n");
    let _ = writeln!(
        c,
        "void {pf}_init({pf}_state *s, {pf}_inputs *i, {pf}_outputs *o) {{\n    (void)s;\n    (void)i;"
    );
    for (k, s) in p.slots.iter().enumerate() {
        let _ = writeln!(
            c,
            "    {} = ({}){};",
            slot_ref(p, n, k as u32),
            c_type(s),
            lit(s.init)
        );
    }
    c.push_str("    o->error_site = 0;\n    o->error_value = 0;\n    o->error_lo = 0;\n    o->error_hi = 0;\n}\n\n");
    let _ = writeln!(
        c,
        "void {pf}_slots(const {pf}_state *s, const {pf}_inputs *i, const {pf}_outputs *o, int64_t *v) {{\n    (void)s;\n    (void)i;\n    (void)o;"
    );
    for k in 0..p.slots.len() {
        let _ = writeln!(c, "    v[{k}] = (int64_t){};", slot_ref(p, n, k as u32));
    }
    c.push_str("}\n");
    c
}

/// The translated statements of a function body, with its expression locals declared.
fn body(p: &Program, src: &Source, n: &Names, stmts: &[statecheck_ir::Stmt]) -> String {
    let pf = &n.prefix;
    let mut locals = BTreeSet::new();
    lets_in_stmts(p, stmts, &mut locals);
    let slot = |s: SlotId| slot_ref(p, n, s);
    let fail = |kind: &str, site: u32, value: &str| {
        format!("return {pf}_fail(o, {kind}, {site}u, {value}, 0, 0);")
    };
    let fail_range = |site: u32, value: &str, lo: i64, hi: i64| {
        format!(
            "return {pf}_fail(o, SC_ERR_RANGE, {site}u, {value}, {}, {});",
            lit(lo),
            lit(hi)
        )
    };
    let cover_comment = |c: u32| match p.covers.get(c as usize) {
        Some(cv) => format!("{} ({})", cv.label.replace("*/", "* /"), src.at(cv.span)),
        None => String::new(),
    };
    let site_comment = |site: u32| match p.sites.get(site as usize) {
        Some(s) => format!(
            "/* site {site}: {} ({}) */",
            s.what.replace("*/", "* /"),
            src.at(s.span)
        ),
        None => String::new(),
    };
    let call = |k: u32| {
        format!(
            "{{ const int e_ = {}(s, i, o); if (e_ != 0) return e_; }}",
            n.procs[k as usize]
        )
    };
    let case = |s: SlotId, k: usize| case_label(n, s, k);
    let hit = |c: u32| format!("o->cover_hits_[{c}] = 1;");
    let mut em = CEmit {
        p,
        slot: &slot,
        fail: &fail,
        fail_range: &fail_range,
        cover_comment: &cover_comment,
        cover_hit: n.count_covers.then_some(&hit as &dyn Fn(u32) -> String),
        site_comment: &site_comment,
        call: &call,
        case_label: &case,
        out: String::new(),
        depth: 1,
        tmp: 0,
    };
    for l in &locals {
        em.out
            .push_str(&format!("    int64_t l{l} = 0;\n    (void)l{l};\n"));
    }
    em.block(stmts);
    em.out
}
