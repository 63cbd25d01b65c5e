fn noret(x: int) -> int { let y = x; }
fn late(x: int) -> int { return x; let z = 1; }
fn colon(x: int): int = x;
fn noret2() -> int { y = 1; return 2; }
fn params(x int) -> int = x;
fn ok() -> int = 1;
