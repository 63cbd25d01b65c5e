// The Feeder: a pneumatic cylinder that pushes the workpiece from the magazine to the
// pick-up position, its stroke 0..100 %, with its speed set by the workpiece's weight. Its
// position is a `continuous` plant variable (docs/hybrid.md): the checker discretizes it on
// the grid of 20 cells of 5 % itself, computes every clock reading T(x_i) = x_i / speed
// exactly and refuses one that is not a whole number of ticks (README.md, "The motion").
// Its two end-position sensors are range predicates on the position.
import "common.sc";

// Speeds (ours, README.md): pushing a light workpiece 2 %/s, a heavy one 0.8 %/s, retracting 4 %/s.
plant chart Feeder {
  input extend: bool = true;     // the valve: push while true, retract while false
  input first: Wp = LIGHT;       // the workpiece lying in the extended Feeder at the start
  input slot: Wp = NONE;         // the magazine's workpiece in front of the pusher
  input event taken;             // token protocol: the Transfer sucked the workpiece off
  output wp: Wp = NONE;          // buffer of size 1: the workpiece being pushed
  output offer: Wp = NONE;       // READY: a workpiece at the pick-up position for the Transfer
  output home: bool = false;     // the home end-position sensor, [0, 5] % (HOME_SENSOR's input)
  output extended: bool = true;  // END_SENSOR, [95, 100] %
  output event took;             // the workpiece taken from the magazine
  // The start: extended, the first workpiece at the pick-up position (README.md, "The start").
  continuous pos: [0 .. 100] = 100;
  grid pos 20;
  sensor home = pos in [0 .. 5];
  sensor extended = pos in [95 .. 100];
  initial Extended / { wp = first; };
  state Home {
    on [extend] / { wp = slot; raise took; }
      -> choice { [slot == HEAVY] -> PushingHeavy; else -> PushingLight; };
  }
  state PushingLight {
    der(pos) = 2;
    on [!extend] -> Retracting;
    on [pos >= 100] -> Extended;
  }
  state PushingHeavy {
    der(pos) = 0.8;
    on [!extend] -> Retracting;
    on [pos >= 100] -> Extended;
  }
  state Extended {
    entry { offer = wp; }
    on taken / { wp = NONE; offer = NONE; };
    on [!extend] -> Retracting;
  }
  state Retracting {
    der(pos) = -4;
    on [extend] -> choice { [wp == HEAVY] -> PushingHeavy; else -> PushingLight; };
    on [pos <= 0] -> Home;
  }
}
