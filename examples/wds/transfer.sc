// The Transfer: a vacuum gripper on a linear axis, 0 % = the pick-up position at the
// Storage, 100 % = the unloading position. Its drive comes in two variants behind one
// interface: the stepper-driven L-Transfer (constant speed) and the DC-driven D-Transfer
// (slower at start-up and slow-down). Its controller is the same for both.
import "common.sc";

// The Transfer's drive and suction: the plant.
interface TransferDrive {
  input cmd: Move;            // the motion command
  input vacuum: bool;         // the suction valve
  input offer: Wp;            // token protocol: the workpiece the Feeder offers at 0 %
  output pos: int[0..100];    // the gripper's position
  output wp: Wp;              // buffer of size 1: the workpiece held by suction
  output to_storage: bool;    // moving towards the Storage
  output event took;          // the workpiece sucked off the Feeder
  output event released;      // the workpiece let go
}

// Suction: takes the offered workpiece at the pick-up position while the vacuum is on, and
// lets it go where the vacuum goes off. (Written once per drive: charts cannot share regions.)

// L-Transfer: a stepper motor, constant speed per load. Speeds in 0.1 %/s: 2 %/s empty or
// with a light workpiece, 0.5 %/s with a heavy one.
chart LTransfer(fast: int[1..1000] = 20, slow: int[1..1000] = 5) implements TransferDrive {
  input cmd: Move = STOP;
  input vacuum: bool = false;
  input offer: Wp = NONE;
  output pos: int[0..100] = 100;
  output wp: Wp = NONE;
  output to_storage: bool = false;
  output event took;
  output event released;
  region motion {
    initial Still;
    state Still {
      on [cmd == TO_STORAGE && pos > 0] -> Backward;
      on [cmd == TO_UNLOAD && pos < 100] -> Forward;
    }
    state Forward {
      on [cmd != TO_UNLOAD] -> Still;
      on after((cell_ms(slow)) ms) [wp == HEAVY] / { pos += CELL; }
        -> choice { [pos == 100 - CELL] -> Still; else -> Forward; };
      on after((cell_ms(fast)) ms) [wp != HEAVY] / { pos += CELL; }
        -> choice { [pos == 100 - CELL] -> Still; else -> Forward; };
    }
    state Backward {
      entry { to_storage = true; }
      exit { to_storage = false; }
      on [cmd != TO_STORAGE] -> Still;
      on after((cell_ms(slow)) ms) [wp == HEAVY] / { pos -= CELL; }
        -> choice { [pos == CELL] -> Still; else -> Backward; };
      on after((cell_ms(fast)) ms) [wp != HEAVY] / { pos -= CELL; }
        -> choice { [pos == CELL] -> Still; else -> Backward; };
    }
  }
  region suction {
    initial Empty;
    state Empty {
      on [vacuum && pos == 0 && offer != NONE] / { wp = offer; raise took; } -> Holding;
    }
    state Holding {
      on [!vacuum] / { wp = NONE; raise released; } -> Empty;
    }
  }
}

// D-Transfer: a DC motor. Its speed profile (ours, README.md): half speed over the 5 % next to
// either end of the stroke (start-up when leaving it, slow-down when approaching it), full
// speed between. Full speeds as for the L-Transfer.
chart DTransfer(fast: int[1..1000] = 20, slow: int[1..1000] = 5) implements TransferDrive {
  input cmd: Move = STOP;
  input vacuum: bool = false;
  input offer: Wp = NONE;
  output pos: int[0..100] = 100;
  output wp: Wp = NONE;
  output to_storage: bool = false;
  output event took;
  output event released;
  region motion {
    initial Still;
    state Still {
      on [cmd == TO_STORAGE && pos > 0] -> Backward;
      on [cmd == TO_UNLOAD && pos < 100] -> Forward;
    }
    state Forward {
      on [cmd != TO_UNLOAD] -> Still;
      on after((cell_ms(slow)) ms) [wp == HEAVY && pos != 0 && pos != 100 - CELL] / { pos += CELL; }
        -> Forward;
      on after((2 * cell_ms(slow)) ms) [wp == HEAVY && (pos == 0 || pos == 100 - CELL)] / { pos += CELL; }
        -> choice { [pos == 100 - CELL] -> Still; else -> Forward; };
      on after((cell_ms(fast)) ms) [wp != HEAVY && pos != 0 && pos != 100 - CELL] / { pos += CELL; }
        -> Forward;
      on after((2 * cell_ms(fast)) ms) [wp != HEAVY && (pos == 0 || pos == 100 - CELL)] / { pos += CELL; }
        -> choice { [pos == 100 - CELL] -> Still; else -> Forward; };
    }
    state Backward {
      entry { to_storage = true; }
      exit { to_storage = false; }
      on [cmd != TO_STORAGE] -> Still;
      on after((cell_ms(slow)) ms) [wp == HEAVY && pos != 100 && pos != CELL] / { pos -= CELL; }
        -> Backward;
      on after((2 * cell_ms(slow)) ms) [wp == HEAVY && (pos == 100 || pos == CELL)] / { pos -= CELL; }
        -> choice { [pos == CELL] -> Still; else -> Backward; };
      on after((cell_ms(fast)) ms) [wp != HEAVY && pos != 100 && pos != CELL] / { pos -= CELL; }
        -> Backward;
      on after((2 * cell_ms(fast)) ms) [wp != HEAVY && (pos == 100 || pos == CELL)] / { pos -= CELL; }
        -> choice { [pos == CELL] -> Still; else -> Backward; };
    }
  }
  region suction {
    initial Empty;
    state Empty {
      on [vacuum && pos == 0 && offer != NONE] / { wp = offer; raise took; } -> Holding;
    }
    state Holding {
      on [!vacuum] / { wp = NONE; raise released; } -> Empty;
    }
  }
}

// The Transfer's controller: fetch a workpiece when the Storage allows it, carry it to the
// unloading position, release it there, and wait for the next ALLOW_RIGHT.
chart TransferController {
  input run: bool = false;
  input allow_right: bool = false;   // the Storage's interlock
  input pos: int[0..100] = 100;      // the drive's position (its encoder)
  input event took;                  // the suction holds the workpiece
  input event released;              // the suction let it go
  output cmd: Move = STOP;
  output vacuum: bool = false;
  output event taken;                // the interlock's answer to the Storage
  initial AtUnload;
  state AtUnload {
    on [run && allow_right] / { cmd = TO_STORAGE; } -> ToStorage;
  }
  state ToStorage {
    on [pos == 0] / { cmd = STOP; vacuum = true; } -> Picking;
  }
  state Picking {
    on took / { raise taken; cmd = TO_UNLOAD; } -> Carrying;
  }
  state Carrying {
    on [pos == 100] / { cmd = STOP; vacuum = false; } -> Releasing;
  }
  state Releasing {
    on released -> AtUnload;
  }
}
