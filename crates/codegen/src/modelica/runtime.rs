//! Modelica functions for the operators Modelica lacks: bitwise and/or/xor on two's-complement
//! integers, shifts, and the literal of an enumeration with a given index. Integer arithmetic
//! only (`div`, `mod`, loops): no `Real`, so results are exact. Emitted only when used.

use super::expr::Used;
use super::names::Names;
use std::fmt::Write;

/// The helper functions `used` needs, indented one level.
pub(crate) fn helpers(n: &Names, used: &Used) -> String {
    let mut o = String::new();
    let bit_ops = [
        (
            used.and,
            &n.helpers.and,
            "and",
            "bx == 1 and by == 1",
            "x == -1 and y == -1",
        ),
        (
            used.or,
            &n.helpers.or,
            "or",
            "bx == 1 or by == 1",
            "x == -1 or y == -1",
        ),
        (
            used.xor,
            &n.helpers.xor,
            "xor",
            "bx <> by",
            "(x == -1) <> (y == -1)",
        ),
    ];
    for (on, name, what, bit, sign) in bit_ops {
        if !on {
            continue;
        }
        // Bits are taken from the least significant end with floor division until both
        // operands are 0 or -1 (all higher bits equal); the sign bits then extend the result.
        let _ = write!(
            o,
            r#"  function {name} "bitwise {what} of two's-complement integers"
    input Integer a;
    input Integer b;
    output Integer r;
  protected
    Integer x;
    Integer y;
    Integer bx;
    Integer by;
    Integer w;
  algorithm
    x := a;
    y := b;
    r := 0;
    w := 1;
    while not ((x == 0 or x == -1) and (y == 0 or y == -1)) loop
      bx := mod(x, 2);
      by := mod(y, 2);
      if {bit} then
        r := r + w;
      end if;
      x := div(x - bx, 2);
      y := div(y - by, 2);
      w := 2 * w;
    end while;
    if {sign} then
      r := r - w;
    end if;
  end {name};

"#
        );
    }
    if used.shl {
        let name = &n.helpers.shl;
        let _ = write!(
            o,
            r#"  function {name} "a << b = a * 2^b, for 0 <= b <= 62"
    input Integer a;
    input Integer b;
    output Integer r;
  algorithm
    r := a;
    for k in 1:b loop
      r := 2 * r;
    end for;
  end {name};

"#
        );
    }
    if used.shr {
        let name = &n.helpers.shr;
        let _ = write!(
            o,
            r#"  function {name} "arithmetic a >> b = floor(a / 2^b), for 0 <= b <= 62"
    input Integer a;
    input Integer b;
    output Integer r;
  algorithm
    r := a;
    for k in 1:b loop
      r := div(r - mod(r, 2), 2);
    end for;
  end {name};

"#
        );
    }
    for &k in &used.of_int {
        let Some(e) = n.enums.get(k) else {
            continue;
        };
        let mut chain = String::new();
        let last = e.literals.len().saturating_sub(1);
        for (v, l) in e.literals.iter().enumerate() {
            if v < last {
                let kw = if v == 0 { "if" } else { "elseif" };
                let _ = write!(chain, "{kw} i == {v} then {}.{l} ", e.name);
            } else if v == 0 {
                let _ = write!(chain, "{}.{l}", e.name);
            } else {
                let _ = write!(chain, "else {}.{l}", e.name);
            }
        }
        let _ = write!(
            o,
            r#"  function {f} "the literal of {t} with index i (0-based; checked by the caller)"
    input Integer i;
    output {t} e;
  algorithm
    e := {chain};
  end {f};

"#,
            f = e.of_int,
            t = e.name
        );
    }
    o
}
