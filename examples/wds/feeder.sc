// The Feeder: a pneumatic cylinder that pushes the workpiece from the magazine to the
// pick-up position (its stroke 0..100 %), with its speed set by the workpiece's weight.
// Hand-discretized on the grid of 20 cells of 5 % (README.md): one transition per cell,
// taken after the cell's crossing time.
import "common.sc";

// Speeds in 0.1 %/s: pushing a light workpiece 2 %/s, a heavy one 0.8 %/s, retracting 4 %/s.
chart Feeder(push_light: int[1..1000] = 20, push_heavy: int[1..1000] = 8, retract: int[1..1000] = 40) {
  input extend: bool = true;     // the valve: push while true, retract while false
  input first: Wp = LIGHT;       // the workpiece lying in the extended Feeder at the start
  input slot: Wp = NONE;         // the magazine's workpiece in front of the pusher
  input event taken;             // token protocol: the Transfer sucked the workpiece off
  output pos: int[0..100] = 100; // the start: extended, the first workpiece at the pick-up position
  output wp: Wp = NONE;          // buffer of size 1: the workpiece being pushed
  output offer: Wp = NONE;       // READY: a workpiece at the pick-up position for the Transfer
  output event took;             // the workpiece taken from the magazine
  initial Extended / { wp = first; };
  state Home {
    on [extend] / { wp = slot; raise took; } -> Pushing;
  }
  state Pushing {
    on [!extend] -> Retracting;
    on after((cell_ms(push_heavy)) ms) [wp == HEAVY] / { pos += CELL; }
      -> choice { [pos == 100 - CELL] -> Extended; else -> Pushing; };
    on after((cell_ms(push_light)) ms) [wp != HEAVY] / { pos += CELL; }
      -> choice { [pos == 100 - CELL] -> Extended; else -> Pushing; };
  }
  state Extended {
    entry { offer = wp; }
    on taken / { wp = NONE; offer = NONE; };
    on [!extend] -> Retracting;
  }
  state Retracting {
    on [extend] -> Pushing;
    on after((cell_ms(retract)) ms) / { pos -= CELL; }
      -> choice { [pos == CELL] -> Home; else -> Retracting; };
  }
}
