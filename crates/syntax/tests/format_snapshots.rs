//! Snapshots of formatted output for representative inputs (`insta`; review a change with
//! `cargo insta review` or `INSTA_UPDATE=always`, and read the diff).

#![allow(clippy::unwrap_used)] // tests may unwrap

use statecheck_syntax::format::format;

fn repo_file(rel: &str) -> String {
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel);
    std::fs::read_to_string(p).unwrap()
}

#[test]
fn linear_drive() {
    insta::assert_snapshot!(format(&repo_file("examples/linear_drive/linear_drive.sc")).unwrap());
}

#[test]
fn small_factory_synthesis() {
    insta::assert_snapshot!(format(&repo_file("examples/synthesis/small_factory.sc")).unwrap());
}

/// Every construct, written badly: no indentation, odd spacing, comments in odd places,
/// redundant and needed parentheses, hex literals, compound assignments, `else if`.
const EVERY_CONSTRUCT: &str = r#"
// header comment


tick   100ms ;
const N:int=0x10;   const M = (N+1)*2 ;
enum Mode{Off,On,   Fault ,}
fn twice(x:int)->int=x*2;
fn clamp(x: int, lo: int, hi: int) -> int { let a = max(x, lo) ; /* keep */ return min(a,hi); }
plant chart P { controllable event start; uncontrollable event done; initial Idle;
marked state Idle{on start->Busy;} state Busy{on done->Idle;} }
chart C {
input event go; input event halt ; input level: int[0..N] = 0;
output mode: Mode = Off; local n: int[-3..3]=0; local event tick2;
invariant small: n<=3 assuming mode!=Fault;
entry{n=0;}
initial Off/{mode=Off;};
history deep;
state Off { on go [(level > 2) && !(n == 1)] / { n += 1 ; raise tick2; } -> On priority 1;
  on halt; }
state On {
  during { if n > 0 { n -= 1; } else if n < 0 { n = -(-n); } else { n = (n); } }
  on after(3 s) -> choice { [level>N/2] -> Off; else / { mode = Fault; } -> J; };
  on after(N) -> Off;
  junction J { [true] -> Off; }
  exit{mode=Off;}
}
region r1 { initial A; state A; }
}
system S { instance c: C; instance ps[2]: P; connect c.mode -> c.mode; order c, ps;
assume !(c.go && c.halt);
requirement never (in(c.On) && c.n > 2); requirement start needs (c.n == 0);
reachable busy: in(c.On);
respond r: c.go => in(c.On) within 2;
observer O { input event e; initial W; state W { on e -> error; } state error; } }
// trailing comment
"#;

#[test]
fn every_construct() {
    insta::assert_snapshot!(format(EVERY_CONSTRUCT).unwrap());
}
