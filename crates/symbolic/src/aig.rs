//! And-Inverter Graphs: the circuit every engine works on.
//!
//! Literals follow AIGER: `2 * var + negated`, variable 0 is the constant false (so literal 0
//! is false and 1 is true). Gates are created in topological order and structurally hashed.

use std::collections::HashMap;

/// A literal: `2 * variable + (1 if negated)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Lit(pub u32);

impl Lit {
    /// The constant false.
    pub const FALSE: Lit = Lit(0);
    /// The constant true.
    pub const TRUE: Lit = Lit(1);

    /// The positive literal of a variable.
    pub fn var_lit(var: u32) -> Lit {
        Lit(var << 1)
    }
    /// Its variable.
    pub fn var(self) -> u32 {
        self.0 >> 1
    }
    /// True when negated.
    pub fn is_neg(self) -> bool {
        self.0 & 1 == 1
    }
    /// The literal without negation.
    pub fn positive(self) -> Lit {
        Lit(self.0 & !1)
    }
    /// The literal negated when `neg`.
    pub fn xor(self, neg: bool) -> Lit {
        Lit(self.0 ^ u32::from(neg))
    }
    /// The constant of a Boolean.
    pub fn constant(b: bool) -> Lit {
        Lit(u32::from(b))
    }
}

impl std::ops::Not for Lit {
    type Output = Lit;
    fn not(self) -> Lit {
        Lit(self.0 ^ 1)
    }
}

/// What a variable is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Node {
    /// Variable 0.
    False,
    /// Primary input number `i`.
    Input(u32),
    /// Latch number `i`.
    Latch(u32),
    /// The conjunction of two earlier literals.
    And(Lit, Lit),
}

impl Node {
    /// The input number of an input node (0 otherwise).
    pub fn input_index(&self) -> usize {
        match self {
            Node::Input(i) => *i as usize,
            _ => 0,
        }
    }
    /// The latch number of a latch node (0 otherwise).
    pub fn latch_index(&self) -> usize {
        match self {
            Node::Latch(i) => *i as usize,
            _ => 0,
        }
    }
}

/// A latch: its variable, next-state function and reset value (`None`: uninitialized).
#[derive(Clone, Debug)]
pub struct Latch {
    /// Its variable.
    pub var: u32,
    /// Next-state literal.
    pub next: Lit,
    /// Reset value; `None` means any initial value.
    pub init: Option<bool>,
}

/// An And-Inverter Graph with inputs, latches, bad-state outputs and invariant constraints.
#[derive(Clone, Debug)]
pub struct Aig {
    /// Every variable, indexed by variable number.
    pub nodes: Vec<Node>,
    /// Variables of the primary inputs.
    pub inputs: Vec<u32>,
    /// The latches.
    pub latches: Vec<Latch>,
    /// Bad-state literals (one per property).
    pub bad: Vec<Lit>,
    /// Invariant constraints (must hold in every step of a trace, including the last).
    pub constraints: Vec<Lit>,
    /// Optional names of inputs, latches and bad outputs (`i`, `l`, `b` symbol sections).
    pub input_names: Vec<Option<String>>,
    /// Names of latches.
    pub latch_names: Vec<Option<String>>,
    /// Names of bad outputs.
    pub bad_names: Vec<Option<String>>,
    /// Justice properties (AIGER 1.9 `J`): each is violated by a run on which every one of its
    /// literals, and every fairness literal, holds infinitely often.
    pub justice: Vec<Vec<Lit>>,
    /// Names of justice properties.
    pub justice_names: Vec<Option<String>>,
    /// Fairness constraints (AIGER 1.9 `F`): each holds infinitely often on the runs the
    /// justice properties speak of.
    pub fairness: Vec<Lit>,
    strash: HashMap<(Lit, Lit), Lit>,
}

impl Default for Aig {
    fn default() -> Self {
        Aig::new()
    }
}

impl Aig {
    /// An empty graph (only the constant).
    pub fn new() -> Aig {
        Aig {
            nodes: vec![Node::False],
            inputs: Vec::new(),
            latches: Vec::new(),
            bad: Vec::new(),
            constraints: Vec::new(),
            input_names: Vec::new(),
            latch_names: Vec::new(),
            bad_names: Vec::new(),
            justice: Vec::new(),
            justice_names: Vec::new(),
            fairness: Vec::new(),
            strash: HashMap::new(),
        }
    }

    /// Number of variables (including the constant).
    pub fn num_vars(&self) -> usize {
        self.nodes.len()
    }

    /// Number of AND gates.
    pub fn num_ands(&self) -> usize {
        self.nodes
            .iter()
            .filter(|n| matches!(n, Node::And(..)))
            .count()
    }

    /// A new primary input.
    pub fn input(&mut self, name: Option<String>) -> Lit {
        let v = self.nodes.len() as u32;
        self.nodes.push(Node::Input(self.inputs.len() as u32));
        self.inputs.push(v);
        self.input_names.push(name);
        Lit::var_lit(v)
    }

    /// A new latch with a reset value; its next state is set later with [`Aig::set_next`].
    pub fn latch(&mut self, init: Option<bool>, name: Option<String>) -> Lit {
        let v = self.nodes.len() as u32;
        self.nodes.push(Node::Latch(self.latches.len() as u32));
        self.latches.push(Latch {
            var: v,
            next: Lit::FALSE,
            init,
        });
        self.latch_names.push(name);
        Lit::var_lit(v)
    }

    /// Set the next-state function of latch number `i`.
    pub fn set_next(&mut self, i: usize, next: Lit) {
        self.latches[i].next = next;
    }

    /// Add a raw AND node without simplification (for readers that must keep numbering).
    pub fn raw_and(&mut self, a: Lit, b: Lit) -> Lit {
        let v = self.nodes.len() as u32;
        self.nodes.push(Node::And(a, b));
        Lit::var_lit(v)
    }

    /// `a ∧ b`, simplified and structurally hashed.
    pub fn and(&mut self, a: Lit, b: Lit) -> Lit {
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        if a == Lit::FALSE || a == !b {
            return Lit::FALSE;
        }
        if a == Lit::TRUE || a == b {
            return b;
        }
        if let Some(&l) = self.strash.get(&(a, b)) {
            return l;
        }
        let l = self.raw_and(a, b);
        self.strash.insert((a, b), l);
        l
    }

    /// `a ∨ b`.
    pub fn or(&mut self, a: Lit, b: Lit) -> Lit {
        !self.and(!a, !b)
    }

    /// `a ⊕ b`.
    pub fn xor(&mut self, a: Lit, b: Lit) -> Lit {
        let x = self.and(a, !b);
        let y = self.and(!a, b);
        self.or(x, y)
    }

    /// `a ↔ b`.
    pub fn iff(&mut self, a: Lit, b: Lit) -> Lit {
        !self.xor(a, b)
    }

    /// `if c then a else b`.
    pub fn mux(&mut self, c: Lit, a: Lit, b: Lit) -> Lit {
        if a == b {
            return a;
        }
        let x = self.and(c, a);
        let y = self.and(!c, b);
        self.or(x, y)
    }

    /// Conjunction of many.
    pub fn and_all(&mut self, lits: impl IntoIterator<Item = Lit>) -> Lit {
        lits.into_iter().fold(Lit::TRUE, |acc, l| self.and(acc, l))
    }

    /// Disjunction of many.
    pub fn or_all(&mut self, lits: impl IntoIterator<Item = Lit>) -> Lit {
        lits.into_iter().fold(Lit::FALSE, |acc, l| self.or(acc, l))
    }

    /// Evaluate every variable given input values and latch values (concrete simulation).
    pub fn simulate(&self, inputs: &[bool], latches: &[bool]) -> Vec<bool> {
        let mut val = vec![false; self.nodes.len()];
        for (v, n) in self.nodes.iter().enumerate() {
            val[v] = match *n {
                Node::False => false,
                Node::Input(i) => inputs.get(i as usize).copied().unwrap_or(false),
                Node::Latch(i) => latches.get(i as usize).copied().unwrap_or(false),
                Node::And(a, b) => lit_val(&val, a) && lit_val(&val, b),
            };
        }
        val
    }

    /// The reset state, uninitialized latches taken as false.
    pub fn reset_state(&self) -> Vec<bool> {
        self.latches
            .iter()
            .map(|l| l.init.unwrap_or(false))
            .collect()
    }
}

/// A literal's value under a simulation result of [`Aig::simulate`].
pub fn lit_val(values: &[bool], l: Lit) -> bool {
    values[l.var() as usize] ^ l.is_neg()
}

impl Aig {
    /// Variables in the cone of influence of the bad outputs, constraints, justice and
    /// fairness literals (through latches' next-state functions).
    pub fn cone(&self) -> Vec<bool> {
        let mut seen = vec![false; self.nodes.len()];
        let mut stack: Vec<u32> = self
            .bad
            .iter()
            .chain(&self.constraints)
            .chain(self.justice.iter().flatten())
            .chain(&self.fairness)
            .map(|l| l.var())
            .collect();
        while let Some(v) = stack.pop() {
            if std::mem::replace(&mut seen[v as usize], true) {
                continue;
            }
            match self.nodes[v as usize] {
                Node::And(a, b) => {
                    stack.push(a.var());
                    stack.push(b.var());
                }
                Node::Latch(i) => stack.push(self.latches[i as usize].next.var()),
                Node::False | Node::Input(_) => {}
            }
        }
        seen
    }

    /// A copy without the logic and latches outside the cone of influence (every input is
    /// kept, in order, so input vectors mean the same).
    pub fn reduced(&self) -> Aig {
        self.reduced_with_latches().0
    }

    /// [`Aig::reduced`], with the index in `self` of each latch kept.
    pub fn reduced_with_latches(&self) -> (Aig, Vec<usize>) {
        let seen = self.cone();
        let mut g = Aig::new();
        let mut map: Vec<Lit> = vec![Lit::FALSE; self.nodes.len()];
        for (i, &v) in self.inputs.iter().enumerate() {
            map[v as usize] = g.input(self.input_names[i].clone());
        }
        let mut kept = Vec::new();
        for (i, l) in self.latches.iter().enumerate() {
            if seen[l.var as usize] {
                map[l.var as usize] = g.latch(l.init, self.latch_names[i].clone());
                kept.push(i);
            }
        }
        for (v, n) in self.nodes.iter().enumerate() {
            if let Node::And(a, b) = *n {
                if seen[v] {
                    let (x, y) = (map[a.var() as usize], map[b.var() as usize]);
                    map[v] = g.and(x.xor(a.is_neg()), y.xor(b.is_neg()));
                }
            }
        }
        let m = |l: Lit| map[l.var() as usize].xor(l.is_neg());
        for (k, &i) in kept.iter().enumerate() {
            g.set_next(k, m(self.latches[i].next));
        }
        g.bad = self.bad.iter().map(|&l| m(l)).collect();
        g.constraints = self.constraints.iter().map(|&l| m(l)).collect();
        g.bad_names = self.bad_names.clone();
        g.justice = self
            .justice
            .iter()
            .map(|j| j.iter().map(|&l| m(l)).collect())
            .collect();
        g.justice_names = self.justice_names.clone();
        g.fairness = self.fairness.iter().map(|&l| m(l)).collect();
        (g, kept)
    }
}
