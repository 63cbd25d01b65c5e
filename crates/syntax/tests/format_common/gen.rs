//! A generator of random `.sc` texts that parse: every construct of the grammar, random
//! layout between tokens (spaces, newlines, blank lines, `//` and `/* */` comments anywhere),
//! redundant parentheses, hex literals, compound assignments, `else if`. Deterministic per
//! seed, so a failing case is reproduced by its seed.

/// A small deterministic PRNG (xorshift64*), enough for generating test inputs.
pub struct Rng(u64);

impl Rng {
    /// A generator for `seed` (any value).
    pub fn new(seed: u64) -> Rng {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A number in `0..n` (`n > 0`).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n.max(1)
    }

    /// True with probability `p` percent.
    pub fn pct(&mut self, p: u64) -> bool {
        self.below(100) < p
    }
}

/// The generator: tokens joined by random separators.
pub struct Gen {
    rng: Rng,
    out: String,
    comments: u32,
}

const NAMES: &[&str] = &[
    "a", "b", "x", "y", "n", "go", "stop", "A", "B", "C", "Idle", "Run",
];
const BINOPS: &[(&str, u8)] = &[
    ("||", 0),
    ("&&", 1),
    ("==", 2),
    ("!=", 2),
    ("<", 2),
    ("<=", 2),
    (">", 2),
    (">=", 2),
    ("|", 3),
    ("^", 4),
    ("&", 5),
    ("<<", 6),
    (">>", 6),
    ("+", 7),
    ("-", 7),
    ("*", 8),
    ("/", 8),
    ("%", 8),
];

impl Gen {
    /// A generator for `seed`.
    pub fn new(seed: u64) -> Gen {
        Gen {
            rng: Rng::new(seed),
            out: String::new(),
            comments: 0,
        }
    }

    /// Emit one token after a random separator.
    fn t(&mut self, tok: &str) {
        if !self.out.is_empty() {
            let sep = match self.rng.below(20) {
                0..=11 => " ".to_string(),
                12..=14 => "\n".to_string(),
                15 => "\n\n   ".to_string(),
                16 => "  ".to_string(),
                17 => {
                    self.comments += 1;
                    format!(" /* c{} */ ", self.comments)
                }
                18 => {
                    self.comments += 1;
                    format!(" // c{}\n", self.comments)
                }
                _ => {
                    self.comments += 1;
                    format!("\n// c{}\n\n", self.comments)
                }
            };
            self.out.push_str(&sep);
        }
        self.out.push_str(tok);
    }

    fn pick(&mut self, opts: &[&'static str]) -> &'static str {
        opts[self.rng.below(opts.len() as u64) as usize]
    }

    fn name(&mut self) -> &'static str {
        NAMES[self.rng.below(NAMES.len() as u64) as usize]
    }

    /// An expression as tokens; returns its binding level (`None` for `if`, 9 unary, 10 atom).
    fn expr(&mut self, depth: u32) -> Option<u8> {
        let mut buf = Gen {
            rng: Rng(self.rng.next() | 1),
            out: String::new(),
            comments: self.comments,
        };
        let lvl = buf.expr_inner(depth);
        self.comments = buf.comments;
        self.t(&buf.out);
        lvl
    }

    fn expr_inner(&mut self, depth: u32) -> Option<u8> {
        let pick = if depth == 0 {
            self.rng.below(4)
        } else {
            self.rng.below(11)
        };
        match pick {
            0 => {
                let v = self.rng.below(300);
                if self.rng.pct(30) {
                    self.t(&format!("0x{v:X}"));
                } else {
                    self.t(&v.to_string());
                }
                Some(10)
            }
            1 => {
                let n = self.name();
                self.t(n);
                if self.rng.pct(20) {
                    self.t(".");
                    let m = self.name();
                    self.t(m);
                }
                Some(10)
            }
            2 => {
                {
                    let s = if self.rng.pct(50) { "true" } else { "false" };
                    self.t(s);
                }
                Some(10)
            }
            3 => {
                self.t("in");
                self.t("(");
                let n = self.name();
                self.t(n);
                self.t(")");
                Some(10)
            }
            4 => {
                {
                    let s = self.pick(&["-", "!", "~"]);
                    self.t(s);
                }
                self.operand(depth - 1, 9, false);
                Some(9)
            }
            5 => {
                {
                    let s = self.pick(&["min", "max", "abs", "f"]);
                    self.t(s);
                }
                self.t("(");
                let n = 1 + self.rng.below(3);
                for i in 0..n {
                    if i > 0 {
                        self.t(",");
                    }
                    self.expr_inner(depth - 1);
                }
                self.t(")");
                Some(10)
            }
            6 => {
                self.t("if");
                self.expr_inner(depth - 1);
                self.t("then");
                self.expr_inner(depth - 1);
                self.t("else");
                self.expr_inner(depth - 1);
                None
            }
            7 => {
                self.t("(");
                let l = self.expr_inner(depth - 1);
                self.t(")");
                l.map(|_| 10)
            }
            _ => {
                let (op, lvl) = BINOPS[self.rng.below(BINOPS.len() as u64) as usize];
                self.operand(depth - 1, lvl, true);
                self.t(op);
                self.operand(depth - 1, lvl + 1, lvl == 2);
                Some(lvl)
            }
        }
    }

    /// An operand that must bind at least at `min` (parenthesised if it does not, or at
    /// random); `no_cmp` also parenthesises a comparison (comparisons do not chain).
    fn operand(&mut self, depth: u32, min: u8, no_cmp: bool) {
        let mut buf = Gen {
            rng: Rng(self.rng.next() | 1),
            out: String::new(),
            comments: self.comments,
        };
        let lvl = buf.expr_inner(depth);
        self.comments = buf.comments;
        let need = match lvl {
            None => true,
            Some(l) => l < min || (no_cmp && l == 2),
        };
        if need || self.rng.pct(10) {
            self.t("(");
            self.t(&buf.out);
            self.t(")");
        } else {
            self.t(&buf.out);
        }
    }

    fn block(&mut self, depth: u32) {
        self.t("{");
        for _ in 0..self.rng.below(4) {
            self.stmt(depth);
        }
        self.t("}");
    }

    fn stmt(&mut self, depth: u32) {
        match self.rng.below(if depth == 0 { 3 } else { 5 }) {
            0 | 1 => {
                let n = self.name();
                self.t(n);
                {
                    let s = self.pick(&["=", "+=", "-="]);
                    self.t(s);
                }
                self.expr(2);
                self.t(";");
            }
            2 => {
                self.t("raise");
                let n = self.name();
                self.t(n);
                self.t(";");
            }
            _ => {
                self.t("if");
                self.expr(2);
                self.block(depth - 1);
                match self.rng.below(3) {
                    0 => {}
                    1 => {
                        self.t("else");
                        self.block(depth - 1);
                    }
                    _ => {
                        self.t("else");
                        self.stmt_if(depth - 1);
                    }
                }
            }
        }
    }

    fn stmt_if(&mut self, depth: u32) {
        self.t("if");
        self.expr(1);
        self.block(depth);
    }

    fn target(&mut self, depth: u32) {
        if depth > 0 && self.rng.pct(15) {
            self.t("choice");
            self.branches(depth - 1);
        } else {
            let n = self.name();
            self.t(n);
            if self.rng.pct(20) {
                self.t(".");
                let m = self.name();
                self.t(m);
            }
        }
    }

    fn branches(&mut self, depth: u32) {
        self.t("{");
        for _ in 0..self.rng.below(3) {
            self.t("[");
            self.expr(2);
            self.t("]");
            self.branch_rest(depth);
        }
        if self.rng.pct(70) {
            self.t("else");
            self.branch_rest(depth);
        }
        self.t("}");
    }

    fn branch_rest(&mut self, depth: u32) {
        if self.rng.pct(30) {
            self.t("/");
            self.block(1);
        }
        self.t("->");
        self.target(depth);
        self.t(";");
    }

    fn transition(&mut self, depth: u32) {
        self.t("on");
        let mut any = false;
        match self.rng.below(4) {
            0 => {}
            1 => {
                self.t("after");
                self.t("(");
                if self.rng.pct(50) {
                    {
                        let s = (1 + self.rng.below(9)).to_string();
                        self.t(&s);
                    }
                    {
                        let s = self.pick(&["ms", "s", "min"]);
                        self.t(s);
                    }
                } else {
                    self.expr(1);
                }
                self.t(")");
                any = true;
            }
            _ => {
                let n = self.name();
                self.t(n);
                any = true;
            }
        }
        if !any || self.rng.pct(50) {
            self.t("[");
            self.expr(3);
            self.t("]");
        }
        if self.rng.pct(30) {
            self.t("/");
            self.block(2);
        }
        if self.rng.pct(80) {
            self.t("->");
            self.target(depth);
        }
        if self.rng.pct(15) {
            self.t("priority");
            {
                let s = (1 + self.rng.below(5)).to_string();
                self.t(&s);
            }
        }
        self.t(";");
    }

    fn body(&mut self, depth: u32) {
        let n = self.rng.below(6);
        for _ in 0..n {
            match self.rng.below(if depth == 0 { 7 } else { 10 }) {
                0 => {
                    {
                        let s = self.pick(&["entry", "during", "exit"]);
                        self.t(s);
                    }
                    self.block(2);
                }
                1 => {
                    self.t("initial");
                    let n = self.name();
                    self.t(n);
                    if self.rng.pct(30) {
                        self.t("/");
                        self.block(1);
                    }
                    self.t(";");
                }
                2 => {
                    self.t("history");
                    {
                        let s = if self.rng.pct(50) { "shallow" } else { "deep" };
                        self.t(s);
                    }
                    self.t(";");
                }
                3 => {
                    self.t("junction");
                    let n = self.name();
                    self.t(n);
                    self.branches(1);
                }
                4..=6 => self.transition(1),
                7 | 8 => {
                    if self.rng.pct(20) {
                        self.t("marked");
                    }
                    self.t("state");
                    let n = self.name();
                    self.t(n);
                    if self.rng.pct(30) {
                        self.t(";");
                    } else {
                        self.t("{");
                        self.body(depth - 1);
                        self.t("}");
                    }
                }
                _ => {
                    self.t("region");
                    let n = self.name();
                    self.t(n);
                    self.t("{");
                    self.body(depth - 1);
                    self.t("}");
                }
            }
        }
    }

    fn ty(&mut self) {
        match self.rng.below(4) {
            0 => self.t("bool"),
            1 => self.t("int"),
            2 => {
                self.t("int");
                self.t("[");
                self.expr(1);
                self.t("..");
                self.expr(1);
                self.t("]");
            }
            _ => {
                let n = self.name();
                self.t(n);
            }
        }
    }

    fn property(&mut self) {
        match self.rng.below(3) {
            0 => {
                self.t("invariant");
                let n = self.name();
                self.t(n);
                self.t(":");
                self.expr(3);
                if self.rng.pct(30) {
                    self.t("assuming");
                    self.expr(2);
                }
            }
            1 => {
                self.t("reachable");
                let n = self.name();
                self.t(n);
                self.t(":");
                self.expr(3);
            }
            _ => {
                self.t("respond");
                let n = self.name();
                self.t(n);
                self.t(":");
                self.expr(2);
                self.t("=>");
                self.expr(2);
                self.t("within");
                self.expr(1);
            }
        }
        self.t(";");
    }

    fn chart_elems(&mut self) {
        for _ in 0..self.rng.below(5) {
            match self.rng.below(4) {
                0 => {
                    {
                        let s = self.pick(&["input", "output", "local"]);
                        self.t(s);
                    }
                    if self.rng.pct(30) {
                        self.t("event");
                        let n = self.name();
                        self.t(n);
                    } else {
                        let n = self.name();
                        self.t(n);
                        self.t(":");
                        self.ty();
                        if self.rng.pct(60) {
                            self.t("=");
                            self.expr(1);
                        }
                    }
                    self.t(";");
                }
                1 => {
                    {
                        let s = if self.rng.pct(50) {
                            "controllable"
                        } else {
                            "uncontrollable"
                        };
                        self.t(s);
                    }
                    self.t("event");
                    let n = self.name();
                    self.t(n);
                    self.t(";");
                }
                2 => self.property(),
                _ => {}
            }
        }
        self.body(2);
        if self.rng.pct(20) {
            self.t("parallel");
            self.t("{");
            for _ in 0..self.rng.below(3) {
                self.t("region");
                let n = self.name();
                self.t(n);
                self.t("{");
                self.body(1);
                self.t("}");
            }
            self.t("}");
        }
    }

    fn item(&mut self) {
        match self.rng.below(8) {
            0 => {
                self.t("const");
                let n = self.name();
                self.t(n);
                if self.rng.pct(50) {
                    self.t(":");
                    self.ty();
                }
                self.t("=");
                self.expr(3);
                self.t(";");
            }
            1 => {
                self.t("enum");
                let n = self.name();
                self.t(n);
                self.t("{");
                let k = 1 + self.rng.below(4);
                for i in 0..k {
                    if i > 0 {
                        self.t(",");
                    }
                    let n = self.name();
                    self.t(n);
                }
                if self.rng.pct(30) {
                    self.t(",");
                }
                self.t("}");
            }
            2 => {
                self.t("fn");
                let n = self.name();
                self.t(n);
                self.t("(");
                let k = self.rng.below(3);
                for i in 0..k {
                    if i > 0 {
                        self.t(",");
                    }
                    let n = self.name();
                    self.t(n);
                    self.t(":");
                    self.ty();
                }
                self.t(")");
                self.t("->");
                self.ty();
                if self.rng.pct(50) {
                    self.t("=");
                    self.expr(4);
                    self.t(";");
                } else {
                    self.t("{");
                    for _ in 0..self.rng.below(3) {
                        self.t("let");
                        let n = self.name();
                        self.t(n);
                        self.t("=");
                        self.expr(3);
                        self.t(";");
                    }
                    self.t("return");
                    self.expr(4);
                    self.t(";");
                    self.t("}");
                }
            }
            3 => {
                self.t("tick");
                {
                    let s = (1 + self.rng.below(500)).to_string();
                    self.t(&s);
                }
                {
                    let s = self.pick(&["ms", "s", "min"]);
                    self.t(s);
                }
                self.t(";");
            }
            4 => {
                self.t("system");
                let n = self.name();
                self.t(n);
                self.t("{");
                for _ in 0..self.rng.below(7) {
                    self.system_elem();
                }
                self.t("}");
            }
            _ => {
                match self.rng.below(5) {
                    0 => self.t("plant"),
                    1 => self.t("requirement"),
                    _ => {}
                }
                self.t("chart");
                let n = self.name();
                self.t(n);
                self.t("{");
                self.chart_elems();
                self.t("}");
            }
        }
    }

    fn system_elem(&mut self) {
        match self.rng.below(8) {
            0 => {
                self.t("instance");
                let n = self.name();
                self.t(n);
                if self.rng.pct(30) {
                    self.t("[");
                    self.expr(1);
                    self.t("]");
                }
                self.t(":");
                let n = self.name();
                self.t(n);
                self.t(";");
            }
            1 => {
                self.t("connect");
                let (a, b) = (self.name(), self.name());
                self.t(a);
                self.t(".");
                self.t(b);
                self.t("->");
                let (a, b) = (self.name(), self.name());
                self.t(a);
                if self.rng.pct(30) {
                    self.t("[");
                    self.t("*");
                    self.t("]");
                }
                self.t(".");
                self.t(b);
                self.t(";");
            }
            2 => {
                self.t("order");
                let n = self.name();
                self.t(n);
                for _ in 0..self.rng.below(3) {
                    self.t(",");
                    let n = self.name();
                    self.t(n);
                }
                self.t(";");
            }
            3 => {
                self.t("assume");
                self.expr(3);
                self.t(";");
            }
            4 => self.property(),
            5 => {
                self.t("requirement");
                if self.rng.pct(50) {
                    self.t("never");
                } else {
                    let n = self.name();
                    self.t(n);
                    self.t("needs");
                }
                self.t("(");
                self.expr(2);
                self.t(")");
                self.t(";");
            }
            _ => {
                self.t("observer");
                let n = self.name();
                self.t(n);
                self.t("{");
                self.chart_elems();
                self.t("}");
            }
        }
    }

    /// A whole random file.
    pub fn file(mut self) -> String {
        for _ in 0..1 + self.rng.below(5) {
            self.item();
        }
        if self.rng.pct(30) {
            self.t("// last\n");
        }
        self.out
    }
}

/// The random file for `seed`.
pub fn random_file(seed: u64) -> String {
    Gen::new(seed).file()
}
