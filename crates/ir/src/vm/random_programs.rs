//! Differential test on random IR programs: the register code against the reference evaluator.
//!
//! The lowering produces only some shapes of programs; random programs exercise every node and
//! statement kind in every combination, with operand ranges that make overflow, division by
//! zero, bad shifts and range errors frequent. After every tick the outcome (including the
//! error kind and site), the slots (also after an error: slots are written at the same moments)
//! and the coverage counters must be identical, and so must the values of compiled
//! property expressions.

use crate::program::*;
use crate::Machine;
use statecheck_base::Span;
use statecheck_syntax::ast::{BinOp, UnOp};

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn chance(&mut self, percent: u64) -> bool {
        self.next() % 100 < percent
    }

    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        let span = (hi as i128 - lo as i128 + 1) as u128;
        (lo as i128 + (self.next() as u128 % span) as i128) as i64
    }
}

const RANGES: [(i64, i64); 7] = [
    (0, 1),
    (0, 7),
    (0, 255),
    (-100, 100),
    (0, 4095),
    (-(1 << 40), 1 << 40),
    (i64::MIN, i64::MAX),
];

const CONSTS: [i64; 14] = [
    0,
    1,
    2,
    3,
    -1,
    7,
    62,
    63,
    255,
    0x80,
    4096,
    1 << 33,
    i64::MAX,
    i64::MIN,
];

const BINOPS: [BinOp; 18] = [
    BinOp::Add,
    BinOp::Sub,
    BinOp::Mul,
    BinOp::Div,
    BinOp::Rem,
    BinOp::Shl,
    BinOp::Shr,
    BinOp::Eq,
    BinOp::Ne,
    BinOp::Lt,
    BinOp::Le,
    BinOp::Gt,
    BinOp::Ge,
    BinOp::BitAnd,
    BinOp::BitOr,
    BinOp::BitXor,
    BinOp::And,
    BinOp::Or,
];

struct Gen {
    rng: Rng,
    nodes: Vec<Node>,
    n_slots: u32,
    n_locals: u32,
    n_sites: u32,
    n_covers: u32,
    n_procs: u32,
    /// Locals bound by an enclosing `Let`.
    bound: Vec<u32>,
}

impl Gen {
    fn push(&mut self, n: Node) -> ExprId {
        self.nodes.push(n);
        self.nodes.len() as u32 - 1
    }

    fn site(&mut self) -> SiteId {
        self.rng.below(self.n_sites as usize) as u32
    }

    fn leaf(&mut self) -> ExprId {
        match self.rng.below(5) {
            0 | 1 => {
                let v = if self.rng.chance(70) {
                    CONSTS[self.rng.below(CONSTS.len())]
                } else {
                    self.rng.range(-5000, 5000)
                };
                self.push(Node::Const(v))
            }
            2 if !self.bound.is_empty() => {
                let l = self.bound[self.rng.below(self.bound.len())];
                self.push(Node::Local(l))
            }
            _ => {
                let s = self.rng.below(self.n_slots as usize) as u32;
                self.push(Node::Slot(s))
            }
        }
    }

    fn expr(&mut self, depth: u32) -> ExprId {
        if depth == 0 || self.rng.chance(25) {
            return self.leaf();
        }
        let d = depth - 1;
        match self.rng.below(14) {
            0..=4 => {
                let op = BINOPS[self.rng.below(BINOPS.len())];
                let (a, b) = (self.expr(d), self.expr(d));
                let site = self.site();
                self.push(Node::Binary(op, a, b, site))
            }
            5 => {
                let op = [UnOp::Not, UnOp::Neg, UnOp::BitNot][self.rng.below(3)];
                let a = self.expr(d);
                self.push(Node::Unary(op, a))
            }
            6 | 7 => {
                let (c, a, b) = (self.expr(d), self.expr(d), self.expr(d));
                self.push(Node::Ite(c, a, b))
            }
            8 => {
                let (a, b) = (self.expr(d), self.expr(d));
                if self.rng.chance(50) {
                    self.push(Node::Min(a, b))
                } else {
                    self.push(Node::Max(a, b))
                }
            }
            9 => {
                let a = self.expr(d);
                let site = self.site();
                self.push(Node::Abs(a, site))
            }
            10 => {
                let a = self.expr(d);
                let (lo, hi) = RANGES[self.rng.below(RANGES.len())];
                let site = self.site();
                self.push(Node::Check(a, lo, hi, site))
            }
            11 => {
                let l = self.rng.below(self.n_locals as usize) as u32;
                let v = self.expr(d);
                self.bound.push(l);
                let body = self.expr(d);
                self.bound.pop();
                self.push(Node::Let(l, v, body))
            }
            12 if self.rng.chance(50) => {
                // An enumeration tested against several literals, a mask test, or a mask
                // computed by a choice with a constant branch: `s & (K ^ (if c then e else 0))`.
                let s = self.rng.below(self.n_slots as usize) as u32;
                let x = self.push(Node::Slot(s));
                if self.rng.chance(35) {
                    let c = self.expr(d);
                    let e = self.expr(d);
                    let k = CONSTS[self.rng.below(CONSTS.len())];
                    let k = self.push(Node::Const(k));
                    let ite = if self.rng.chance(50) {
                        self.push(Node::Ite(c, e, k))
                    } else {
                        self.push(Node::Ite(c, k, e))
                    };
                    let m = self.push(Node::Const(0xFF));
                    let ops = [BinOp::BitAnd, BinOp::BitXor];
                    let inner = ops[self.rng.below(2)];
                    let inner = self.push(Node::Binary(inner, m, ite, u32::MAX));
                    let outer = ops[self.rng.below(2)];
                    self.push(Node::Binary(outer, x, inner, u32::MAX))
                } else if self.rng.chance(50) {
                    let mut e = None;
                    for _ in 0..2 + self.rng.below(3) {
                        let k = [0, 1, 2, 3, 5, 7, 30, 31, 32, -1][self.rng.below(10)];
                        let k = self.push(Node::Const(k));
                        let t = self.push(Node::Binary(BinOp::Eq, x, k, u32::MAX));
                        e = Some(match e {
                            None => t,
                            Some(e) => self.push(Node::Binary(BinOp::Or, e, t, u32::MAX)),
                        });
                    }
                    e.unwrap_or(x)
                } else {
                    let k = CONSTS[self.rng.below(CONSTS.len())];
                    let k = self.push(Node::Const(k));
                    let m = self.push(Node::Binary(BinOp::BitAnd, x, k, u32::MAX));
                    let zero = self.push(Node::Const(0));
                    let op = if self.rng.chance(50) {
                        BinOp::Eq
                    } else {
                        BinOp::Ne
                    };
                    self.push(Node::Binary(op, m, zero, u32::MAX))
                }
            }
            _ => {
                // Flag patterns of the kind the lowering produces: a comparison with a
                // constant, or `if c then K else 0`.
                let a = self.leaf();
                let k = self.rng.range(-2, 8);
                let k = self.push(Node::Const(k));
                if self.rng.chance(50) {
                    let op = BINOPS[7 + self.rng.below(6)];
                    self.push(Node::Binary(op, a, k, u32::MAX))
                } else {
                    let zero = self.push(Node::Const(0));
                    self.push(Node::Ite(a, k, zero))
                }
            }
        }
    }

    fn block(&mut self, depth: u32, proc_: Option<u32>) -> Vec<Stmt> {
        let n = self.rng.below(7);
        (0..n).map(|_| self.stmt(depth, proc_)).collect()
    }

    fn stmt(&mut self, depth: u32, proc_: Option<u32>) -> Stmt {
        let choice = if depth == 0 { 0 } else { self.rng.below(10) };
        match choice {
            0..=4 => {
                let slot = self.rng.below(self.n_slots as usize) as u32;
                // Small constants often: flags that later statements test.
                let expr = if self.rng.chance(30) {
                    let v = [0, 1, 2, 0, 1, 2, 31, 32, -1][self.rng.below(9)];
                    self.push(Node::Const(v))
                } else {
                    self.expr(3)
                };
                let site = self.rng.chance(60).then(|| self.site());
                Stmt::Assign { slot, expr, site }
            }
            5 | 6 => Stmt::If {
                cond: if self.rng.chance(30) {
                    let s = self.rng.below(self.n_slots as usize) as u32;
                    self.push(Node::Slot(s))
                } else {
                    self.expr(3)
                },
                then: self.block(depth - 1, proc_),
                otherwise: if self.rng.chance(50) {
                    self.block(depth - 1, proc_)
                } else {
                    Vec::new()
                },
            },
            7 => Stmt::Switch {
                slot: self.rng.below(self.n_slots as usize) as u32,
                cases: (0..1 + self.rng.below(4))
                    .map(|_| self.block(depth - 1, proc_))
                    .collect(),
            },
            8 => {
                // Procedures call only later ones: no recursion.
                let first = proc_.map_or(0, |p| p + 1);
                if first < self.n_procs {
                    let id = first + self.rng.below((self.n_procs - first) as usize) as u32;
                    Stmt::Call(id)
                } else {
                    Stmt::Cover(self.rng.below(self.n_covers as usize) as u32)
                }
            }
            _ => Stmt::Cover(self.rng.below(self.n_covers as usize) as u32),
        }
    }
}

fn random_program(seed: u64) -> Program {
    let mut g = Gen {
        rng: Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1),
        nodes: Vec::new(),
        n_slots: 0,
        n_locals: 3,
        n_sites: 6,
        n_covers: 4,
        n_procs: 0,
        bound: Vec::new(),
    };
    g.n_slots = 4 + g.rng.below(8) as u32;
    g.n_procs = g.rng.below(5) as u32;
    let n_inputs = 1 + g.rng.below(3) as u32;
    let slots: Vec<Slot> = (0..g.n_slots)
        .map(|i| {
            let (lo, hi) = RANGES[g.rng.below(RANGES.len())];
            let init = g.rng.range(lo.max(-3), hi.min(3));
            Slot {
                name: format!("s{i}"),
                role: SlotRole::Var {
                    instance: 0,
                    var: i,
                },
                lo,
                hi,
                init,
                display: ValueKind::Int,
            }
        })
        .collect();
    let n_state = (g.n_slots - n_inputs) as usize;
    let inputs = (n_state as u32..g.n_slots)
        .map(|slot| Input {
            slot,
            name: format!("s{slot}"),
            is_event: false,
            instance: 0,
            var: slot,
            rate: None,
        })
        .collect();
    let procs = (0..g.n_procs)
        .map(|p| Proc {
            name: format!("p{p}"),
            body: g.block(2, Some(p)),
        })
        .collect();
    let step = g.block(3, None);
    let properties = (0..3)
        .map(|k| {
            let expr = g.expr(3);
            Property {
                name: format!("prop{k}"),
                kind: PropertyKind::Invariant {
                    expr,
                    assuming: None,
                },
                goal: Goal::Always {
                    when: None,
                    holds: expr,
                },
                span: Span::default(),
            }
        })
        .collect();
    let sites = (0..g.n_sites)
        .map(|k| Site {
            span: Span::default(),
            instance: None,
            state: String::new(),
            what: format!("site {k}"),
        })
        .collect();
    let covers = (0..g.n_covers)
        .map(|k| Cover {
            instance: 0,
            kind: CoverKind::State(k),
            label: format!("cover {k}"),
            span: Span::default(),
            expected_unreached: false,
        })
        .collect();
    Program {
        name: format!("random{seed}"),
        slots,
        n_state,
        inputs,
        nodes: g.nodes,
        procs,
        step,
        sites,
        covers,
        instances: Vec::new(),
        order: Vec::new(),
        assumes: Vec::new(),
        properties,
        temporal: Vec::new(),
        fairness: Vec::new(),
        started: 0,
        n_locals: g.n_locals as usize,
        tick_ms: None,
        run_cache: Default::default(),
    }
}

#[test]
fn register_code_matches_the_reference_evaluator_on_random_programs() {
    let mut errors = 0;
    let mut ticks = 0;
    let mut calls = 0;
    let mut sets = 0;
    for seed in 1..=3000u64 {
        let p = random_program(seed);
        assert!(p.code().runnable);
        let has = |f: fn(&super::Op) -> bool| p.code().ops.iter().any(f) as u32;
        calls += has(|op| matches!(op, super::Op::Call { .. }));
        sets += has(|op| matches!(op, super::Op::JIn { .. } | super::Op::InSet { .. }));
        let mut fast = Machine::new(&p);
        let mut slow = Machine::new(&p);
        fast.enable_coverage();
        slow.enable_coverage();
        let mut rng = Rng(seed | 1);
        for tick in 0..60 {
            for inp in &p.inputs {
                let s = &p.slots[inp.slot as usize];
                let v = rng.range(s.lo, s.hi);
                fast.set(inp.slot, v);
                slow.set(inp.slot, v);
            }
            let (a, b) = (fast.step(), slow.step_reference());
            ticks += 1;
            assert_eq!(a, b, "seed {seed}, tick {tick}: different outcome");
            assert_eq!(
                fast.slots(),
                slow.slots(),
                "seed {seed}, tick {tick}: different slots"
            );
            assert_eq!(fast.coverage(), slow.coverage(), "seed {seed}, tick {tick}");
            for prop in &p.properties {
                if let PropertyKind::Invariant { expr, .. } = prop.kind {
                    assert_eq!(
                        fast.eval(expr),
                        crate::eval(&p.nodes, slow.slots(), expr),
                        "seed {seed}, tick {tick}: property value"
                    );
                }
            }
            if a.is_err() {
                errors += 1;
                break;
            }
        }
    }
    // The programs must exercise both outcomes.
    assert!(
        errors > 500 && ticks > 50_000,
        "{errors} errors in {ticks} ticks"
    );
    // And calls that are not inlined.
    assert!(calls > 300, "{calls} programs with calls");
    // And membership tests.
    assert!(sets > 300, "{sets} programs with membership tests");
}

/// A program over `n` integer slots (the last one an input) with the given code.
fn handmade(n: u32, nodes: Vec<Node>, procs: Vec<Vec<Stmt>>, step: Vec<Stmt>) -> Program {
    let mut p = random_program(1);
    p.slots.truncate(1);
    p.slots.resize(n as usize, p.slots[0].clone());
    for (i, s) in p.slots.iter_mut().enumerate() {
        (s.lo, s.hi, s.init) = (0, 9, 0);
        s.name = format!("s{i}");
    }
    p.n_state = n as usize - 1;
    p.inputs.truncate(1);
    p.inputs[0].slot = n - 1;
    p.nodes = nodes;
    p.procs = procs
        .into_iter()
        .enumerate()
        .map(|(k, body)| Proc {
            name: format!("p{k}"),
            body,
        })
        .collect();
    p.step = step;
    p.properties.clear();
    p
}

/// A flag set before a call and tested after it is not known after the call: the callee may
/// change it (here when the input is 1).
#[test]
fn a_call_forgets_known_register_values() {
    let assign = |slot, expr| Stmt::Assign {
        slot,
        expr,
        site: None,
    };
    // Nodes: 0 = const 0, 1 = const 1, 2 = slot 0 (the flag), 3 = slot 2 (the input).
    let nodes = vec![Node::Const(0), Node::Const(1), Node::Slot(0), Node::Slot(2)];
    // Called twice and not small: not inlined.
    let proc_ = vec![
        Stmt::If {
            cond: 3,
            then: vec![assign(0, 1)],
            otherwise: Vec::new(),
        },
        Stmt::Cover(0),
        Stmt::Cover(1),
        Stmt::Cover(2),
        Stmt::Cover(3),
    ];
    let step = vec![
        assign(0, 0),
        Stmt::Call(0),
        Stmt::If {
            cond: 2,
            then: vec![assign(1, 1)],
            otherwise: Vec::new(),
        },
        Stmt::Call(0),
    ];
    let p = handmade(3, nodes, vec![proc_], step);
    assert!(p
        .code()
        .ops
        .iter()
        .any(|op| matches!(op, super::Op::Call { .. })));
    for input in [0, 1] {
        let mut m = Machine::new(&p);
        m.set(2, input);
        m.step().expect("no error");
        assert_eq!(m.get(1), input, "input {input}");
    }
}

/// An operand read from a local is kept when a later operand rebinds that local (the tree
/// evaluator has read it before): `let l = s0 in (l | (let l = s1 in l))` and the same with
/// `+`, whose value is `s0 | s1` (`s0 + s1`), not `s1 | s1`.
#[test]
fn an_operand_read_from_a_local_survives_its_rebinding() {
    for op in [BinOp::BitOr, BinOp::Add, BinOp::Lt] {
        let nodes = vec![
            Node::Slot(0),
            Node::Slot(1),
            Node::Local(0),
            Node::Let(0, 1, 2),
            Node::Binary(op, 2, 3, 0),
            Node::Let(0, 0, 4),
        ];
        let step = vec![Stmt::Assign {
            slot: 2,
            expr: 5,
            site: None,
        }];
        let mut p = handmade(4, nodes, Vec::new(), step);
        p.slots[0].init = 1;
        p.slots[1].init = 6;
        let mut m = Machine::new(&p);
        m.step().expect("no error");
        let want = statecheck_model::ops::binary(op, 1, 6).expect("no error");
        assert_eq!(m.get(2), want, "{op:?}");
    }
}

/// A program with more registers than [`super::Reg`] can number runs on the reference
/// evaluator, with the same results.
#[test]
fn programs_too_big_for_the_register_code_run_on_the_reference_evaluator() {
    let n = 40_000u32;
    let nodes = vec![Node::Slot(n - 2), Node::Const(1)];
    let add = Node::Binary(BinOp::Add, 0, 1, 0);
    let nodes = [nodes, vec![add]].concat();
    let step = vec![Stmt::Assign {
        slot: n - 2,
        expr: 2,
        site: Some(1),
    }];
    let p = handmade(n, nodes, Vec::new(), step);
    assert!(!p.code().runnable);
    let mut m = Machine::new(&p);
    for tick in 1..=9 {
        m.step().expect("in range");
        assert_eq!(m.get(n - 2), tick);
    }
    assert_eq!(
        m.step().map_err(|e| e.kind),
        Err(crate::RuntimeErrorKind::Range {
            value: 10,
            lo: 0,
            hi: 9
        })
    );
}
