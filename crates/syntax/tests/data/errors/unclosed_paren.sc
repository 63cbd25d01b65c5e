const A = (1 + 2;
const B = min(1, 2;
const C = x[1;
const D = in(c.Go;
const E = 1;
