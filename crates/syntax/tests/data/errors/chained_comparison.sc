const A = 0 < x < 10;
const B = a == b == c;
const C = 0 < x && x < 10;
