const A = 0x;
const B = 0b102;
const C = 0xZZ;
const D = 0b;
const E = 0x1F;
