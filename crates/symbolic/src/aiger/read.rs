//! Reading AIGER 1.9 (ASCII `aag` and binary `aig`) into an [`Aig`].
//!
//! Errors name the line (or, in the binary AND section, the byte offset) and never panic.

use crate::aig::{Aig, Lit};

/// A parse error with its position.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AigerError {
    /// `line N` or `byte N`.
    pub at: String,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for AigerError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.at, self.message)
    }
}

struct Cursor<'a> {
    b: &'a [u8],
    pos: usize,
    line: usize,
}

impl<'a> Cursor<'a> {
    fn err(&self, message: impl Into<String>) -> AigerError {
        AigerError {
            at: format!("line {}", self.line),
            message: message.into(),
        }
    }

    /// The next line's numbers (at least `min`, at most `max`).
    fn numbers(&mut self, min: usize, max: usize, what: &str) -> Result<Vec<u64>, AigerError> {
        if self.pos >= self.b.len() {
            return Err(AigerError {
                at: format!("line {}", self.line + 1),
                message: format!("unexpected end of file, expected {what}"),
            });
        }
        let end = self.b[self.pos..]
            .iter()
            .position(|&c| c == b'\n')
            .map_or(self.b.len(), |e| self.pos + e);
        let text = &self.b[self.pos..end];
        self.pos = end + 1;
        self.line += 1;
        let text = std::str::from_utf8(text).map_err(|_| self.err("not ASCII text"))?;
        let mut out = Vec::new();
        for tok in text.split_ascii_whitespace() {
            out.push(
                tok.parse::<u64>()
                    .map_err(|_| self.err(format!("`{tok}` is not a number ({what})")))?,
            );
        }
        if out.len() < min || out.len() > max {
            return Err(self.err(format!(
                "expected {what}: {min}{} number(s), found {}",
                if max > min {
                    format!(" to {max}")
                } else {
                    String::new()
                },
                out.len()
            )));
        }
        Ok(out)
    }
}

enum Def {
    None,
    Input(Lit),
    Latch(Lit),
    And(u32, u32),
}

/// Parse an AIGER file (ASCII or binary, detected from the header).
pub fn parse(bytes: &[u8]) -> Result<Aig, AigerError> {
    let mut c = Cursor {
        b: bytes,
        pos: 0,
        line: 0,
    };
    let head_end = bytes
        .iter()
        .position(|&x| x == b'\n')
        .unwrap_or(bytes.len());
    let head = std::str::from_utf8(&bytes[..head_end]).unwrap_or("");
    let binary = if head.starts_with("aag") {
        false
    } else if head.starts_with("aig") {
        true
    } else {
        return Err(AigerError {
            at: "line 1".into(),
            message: "not an AIGER file (expected `aag` or `aig` header)".into(),
        });
    };
    c.pos = 3.min(bytes.len());
    let h = c.numbers(5, 9, "header M I L O A [B C J F]")?;
    let get = |i: usize| h.get(i).copied().unwrap_or(0);
    let (m, ni, nl, no, na, nb, nc, nj, nf) = (
        get(0),
        get(1),
        get(2),
        get(3),
        get(4),
        get(5),
        get(6),
        get(7),
        get(8),
    );
    let herr = |msg: String| AigerError {
        at: "line 1".into(),
        message: msg,
    };
    if nj.max(nf) > bytes.len() as u64 {
        return Err(herr(format!(
            "{nj} justice and {nf} fairness properties are more than the file can define"
        )));
    }
    if m > u64::from(u32::MAX >> 2) {
        return Err(herr(format!("too many variables ({m})")));
    }
    // The counts come from an untrusted file: their sum may overflow.
    let defined = ni
        .checked_add(nl)
        .and_then(|x| x.checked_add(na))
        .ok_or_else(|| herr(format!("I + L + A = {ni} + {nl} + {na} overflows")))?;
    if binary && defined != m {
        return Err(herr(format!(
            "binary AIGER needs M = I + L + A ({m} != {defined})"
        )));
    }
    if defined > m {
        return Err(herr(format!(
            "M = {m} is smaller than I + L + A = {defined}"
        )));
    }
    // Sanity bound so that a corrupt header cannot make us allocate without limit.
    if m > (bytes.len() as u64 + 1) * 4 + 64 {
        return Err(herr(format!("M = {m} is larger than the file can define")));
    }
    let m = m as u32;
    let maxlit = 2 * m + 1;
    let mut g = Aig::new();
    let mut defs: Vec<Def> = (0..=m).map(|_| Def::None).collect();
    let mut define = |c: &Cursor, v: u64, d: Def| -> Result<(), AigerError> {
        if v == 0 || v > u64::from(m) {
            return Err(c.err(format!("variable {v} is outside 1..{m}")));
        }
        if !matches!(defs[v as usize], Def::None) {
            return Err(c.err(format!("variable {v} is defined twice")));
        }
        defs[v as usize] = d;
        Ok(())
    };
    let check_lit = |c: &Cursor, l: u64| -> Result<u32, AigerError> {
        if l > u64::from(maxlit) {
            Err(c.err(format!("literal {l} exceeds the maximum {maxlit}")))
        } else {
            Ok(l as u32)
        }
    };
    for i in 0..ni {
        let lit = if binary {
            2 * (i + 1)
        } else {
            let v = c.numbers(1, 1, "an input literal")?[0];
            if v % 2 == 1 {
                return Err(c.err("an input literal must be even"));
            }
            v
        };
        let x = g.input(None);
        define(&c, lit / 2, Def::Input(x))?;
    }
    let mut latch_raw = Vec::new();
    for i in 0..nl {
        let nums = if binary {
            let mut v = vec![2 * (ni + i + 1)];
            v.extend(c.numbers(1, 2, "a latch: next [reset]")?);
            v
        } else {
            c.numbers(2, 3, "a latch: current next [reset]")?
        };
        if nums[0] % 2 == 1 {
            return Err(c.err("a latch literal must be even"));
        }
        let next = check_lit(&c, nums[1])?;
        let init = match nums.get(2).copied() {
            None | Some(0) => Some(false),
            Some(1) => Some(true),
            Some(r) if r == nums[0] => None,
            Some(r) => {
                return Err(c.err(format!(
                    "latch reset {r} must be 0, 1 or the latch's own literal {}",
                    nums[0]
                )))
            }
        };
        let x = g.latch(init, None);
        define(&c, nums[0] / 2, Def::Latch(x))?;
        latch_raw.push(next);
    }
    let mut outs = Vec::new();
    for _ in 0..no {
        outs.push({
            let v = c.numbers(1, 1, "an output literal")?[0];
            check_lit(&c, v)?
        });
    }
    let mut bads = Vec::new();
    for _ in 0..nb {
        bads.push({
            let v = c.numbers(1, 1, "a bad-state literal")?[0];
            check_lit(&c, v)?
        });
    }
    let mut cons = Vec::new();
    for _ in 0..nc {
        cons.push({
            let v = c.numbers(1, 1, "a constraint literal")?[0];
            check_lit(&c, v)?
        });
    }
    let mut justice_sizes = Vec::new();
    for _ in 0..nj {
        let n = c.numbers(1, 1, "the size of a justice property")?[0];
        // Each literal takes a line of the file.
        if n > bytes.len() as u64 {
            return Err(c.err(format!(
                "a justice property of {n} literals is larger than the file"
            )));
        }
        justice_sizes.push(n);
    }
    let mut justice_raw = Vec::new();
    for &n in &justice_sizes {
        let mut j = Vec::new();
        for _ in 0..n {
            let v = c.numbers(1, 1, "a justice literal")?[0];
            j.push(check_lit(&c, v)?);
        }
        justice_raw.push(j);
    }
    let mut fair_raw = Vec::new();
    for _ in 0..nf {
        let v = c.numbers(1, 1, "a fairness literal")?[0];
        fair_raw.push(check_lit(&c, v)?);
    }
    for i in 0..na {
        if binary {
            let lhs = 2 * (ni + nl + i + 1);
            let d0 = delta(&mut c)?;
            let d1 = delta(&mut c)?;
            let r0 = lhs
                .checked_sub(d0)
                .ok_or_else(|| c.err_byte("delta exceeds the gate"))?;
            let r1 = r0
                .checked_sub(d1)
                .ok_or_else(|| c.err_byte("delta exceeds the gate"))?;
            define(&c, lhs / 2, Def::And(r0 as u32, r1 as u32))?;
        } else {
            let v = c.numbers(3, 3, "an AND gate: lhs rhs0 rhs1")?;
            if v[0] % 2 == 1 {
                return Err(c.err("an AND gate's output literal must be even"));
            }
            let (a, b) = (check_lit(&c, v[1])?, check_lit(&c, v[2])?);
            define(&c, v[0] / 2, Def::And(a, b))?;
        }
    }
    // Symbol table and comments.
    let rest = &bytes[c.pos.min(bytes.len())..];
    let mut names_i = vec![None; ni as usize];
    let mut names_l = vec![None; nl as usize];
    let mut names_b = vec![None; nb as usize];
    let mut names_j = vec![None; nj as usize];
    for line in rest.split(|&x| x == b'\n') {
        let Ok(t) = std::str::from_utf8(line) else {
            break;
        };
        if t == "c" || t.starts_with("c ") {
            break;
        }
        let Some((k, name)) = t.split_once(' ') else {
            continue;
        };
        // The kind is the line's first character, which need not be one byte long.
        let Some(kind) = k.chars().next() else {
            continue;
        };
        let Ok(idx) = k[kind.len_utf8()..].parse::<usize>() else {
            continue;
        };
        let slot = match kind {
            'i' => names_i.get_mut(idx),
            'l' => names_l.get_mut(idx),
            'b' => names_b.get_mut(idx),
            'j' => names_j.get_mut(idx),
            _ => None,
        };
        if let Some(s) = slot {
            *s = Some(name.to_string());
        }
    }
    // Resolve AND gates in topological order.
    let mut lits: Vec<Option<Lit>> = vec![None; (m + 1) as usize];
    lits[0] = Some(Lit::FALSE);
    for (v, d) in defs.iter().enumerate() {
        match d {
            Def::Input(x) | Def::Latch(x) => lits[v] = Some(*x),
            _ => {}
        }
    }
    let mut on_stack = vec![false; (m + 1) as usize];
    let mut resolve = |g: &mut Aig, l: u32| -> Result<Lit, AigerError> {
        let root = l / 2;
        let mut stack = vec![(root, false)];
        while let Some((v, expanded)) = stack.pop() {
            if lits[v as usize].is_some() {
                continue;
            }
            let Def::And(a, b) = defs[v as usize] else {
                return Err(AigerError {
                    at: "file".into(),
                    message: format!("variable {v} is used but never defined"),
                });
            };
            let (la, lb) = (lits[(a / 2) as usize], lits[(b / 2) as usize]);
            if let (Some(la), Some(lb)) = (la, lb) {
                let x = g.and(la.xor(a % 2 == 1), lb.xor(b % 2 == 1));
                lits[v as usize] = Some(x);
                continue;
            }
            if expanded || on_stack[v as usize] {
                return Err(AigerError {
                    at: "file".into(),
                    message: format!("AND gate {} depends on itself (a cycle)", 2 * v),
                });
            }
            on_stack[v as usize] = true;
            stack.push((v, true));
            stack.push((a / 2, false));
            stack.push((b / 2, false));
        }
        Ok(lits[root as usize].unwrap_or(Lit::FALSE).xor(l % 2 == 1))
    };
    for (i, next) in latch_raw.iter().enumerate() {
        let x = resolve(&mut g, *next)?;
        g.set_next(i, x);
    }
    let mut bad = Vec::new();
    // Outputs are the properties of AIGER 1.0 files only (no bad and no justice section).
    let source = if nb > 0 || nj > 0 { &bads } else { &outs };
    for &b in source {
        bad.push(resolve(&mut g, b)?);
    }
    for &cl in &cons {
        let x = resolve(&mut g, cl)?;
        g.constraints.push(x);
    }
    for j in &justice_raw {
        let mut lits = Vec::with_capacity(j.len());
        for &l in j {
            lits.push(resolve(&mut g, l)?);
        }
        g.justice.push(lits);
    }
    for &f in &fair_raw {
        let x = resolve(&mut g, f)?;
        g.fairness.push(x);
    }
    g.justice_names = names_j;
    g.bad = bad;
    g.input_names = names_i;
    g.latch_names = names_l;
    g.bad_names = if nb > 0 {
        names_b
    } else {
        vec![None; g.bad.len()]
    };
    Ok(g)
}

impl Cursor<'_> {
    fn err_byte(&self, message: &str) -> AigerError {
        AigerError {
            at: format!("byte {}", self.pos),
            message: message.into(),
        }
    }
}

fn delta(c: &mut Cursor) -> Result<u64, AigerError> {
    let mut x: u64 = 0;
    let mut shift = 0;
    loop {
        let Some(&b) = c.b.get(c.pos) else {
            return Err(c.err_byte("unexpected end of file in the AND section"));
        };
        c.pos += 1;
        if shift > 35 {
            return Err(c.err_byte("delta too large"));
        }
        x |= u64::from(b & 0x7f) << shift;
        if b & 0x80 == 0 {
            return Ok(x);
        }
        shift += 7;
    }
}
