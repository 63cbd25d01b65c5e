const A = 1 + if a then 1 else 2;
const B = if a then 1;
const C = if a 1 else 2;
const D = if a then 1 else 2;
