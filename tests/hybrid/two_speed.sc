// A feeder that pushes a light (2 %/s) or a heavy (0.8 %/s) workpiece, then retracts by
// itself (4 %/s): the workpiece type is the environment's discrete choice, and the
// collision area is pos >= 95 (the WDS parameters, examples/wds/README.md, ours).
//
// Hand derivation (tick 1.25 s, 20 cells of 5 %), light first: the choice in tick 1 enters
// Light in tick 1, so the motion starts at 1.25 s.
// - at_home ([0 .. 5]) is left when pos passes 5: 1.25 + 5/2 = 3.75 s (tick 3; the sensor
//   reads false from tick 4).
// - in_area ([95 .. 100]) is entered at 95: 1.25 + 95/2 = 48.75 s (tick 39).
// - pos reaches 100 at 1.25 + 50 = 51.25 s (tick 41): Light -> Back in tick 41.
// - retracting from 51.25 s: in_area left at 95: 51.25 + 5/4 = 52.5 s (tick 42; false from
//   tick 43); at_home entered at 5: 51.25 + 95/4 = 75 s (tick 60); pos 0 at 76.25 s (tick
//   61): Back -> Home in tick 61.
// - The next choice is at tick 62 (77.5 s): heavy enters Heavy in tick 62, at_home is left at
//   77.5 + 5/0.8 = 83.75 s (tick 67) and in_area entered at 77.5 + 95/0.8 = 77.5 + 118.75 =
//   196.25 s (tick 157): 118.75 s after the push began.
// Heavy first: the motion starts at 1.25 s; at_home left at 1.25 + 6.25 = 7.5 s (tick 6),
// in_area entered at 1.25 + 118.75 = 120 s (tick 96).
tick 1250 ms;

plant chart Feeder {
  input light: bool = false;
  input heavy: bool = false;
  output at_home: bool;
  output in_area: bool;
  continuous pos: [0 .. 100] = 0;
  grid pos 20;
  sensor at_home = pos in [0 .. 5];
  sensor in_area = pos in [95 .. 100];

  initial Home;
  state Home {
    on [light] -> Light;
    on [heavy && !light] -> Heavy;
  }
  state Light {
    der(pos) = 2;
    on [pos >= 100] -> Back;
  }
  state Heavy {
    der(pos) = 0.8;
    on [pos >= 100] -> Back;
  }
  state Back {
    der(pos) = -4;
    on [pos <= 0] -> Home;
  }
}

system Station {
  instance feeder: Feeder;
  invariant outside: !feeder.in_area;
}
