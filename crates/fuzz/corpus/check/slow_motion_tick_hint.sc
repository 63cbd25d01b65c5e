// Speeds given by a chart parameter (in tenths of % per second), one copy per instance.
// Hand derivation (tick 1.25 s, cells of 5 %): `go` is first seen in tick 1, so Move is
// entered in tick 1 at the earliest. Light, 2 %/s: 2.5 s = 2 ticks per cell, at_end (95 %,
// 19 cells) first in tick 1 + 38 = 39. Heavy, 0.8 %/s: 6.25 s = 5 ticks per cell, at_end
// in tick 1 + 95 = 96 (118.75 s after the push began).
tick 1250 ms;

plant chart Mover(speed_tenths: int) {
  input go: bool = false;
  output at_end: bool;
  continuous pos: [0 .. 100] = 0;
  grid pos 20;
  sensor at_end = pos in [95 .. 100];

  initial Home;
  state Home { on [go] -> Move; }
  state Move {
    der(pos) = speed_tenths / 9223372036854775808;
    on [pos >= 100] -> Home;
  }
}

system Pair {
  instance light: Mover(20);
  instance heavy: Mover(speed_tenths = 8);
  invariant light_end: !light.at_end;
  invariant heavy_end: !heavy.at_end;
}
