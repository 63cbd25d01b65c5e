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

// Suction (region `suction`): takes the offered workpiece at the pick-up position while the
// vacuum is on, and lets it go where the vacuum goes off. The motion states are split by
// load (der is per state): the load never changes while the drive moves.

// L-Transfer: a stepper motor, constant speed per load: 2 %/s empty or with a light
// workpiece, 0.5 %/s with a heavy one.
plant chart LTransfer implements TransferDrive {
  input cmd: Move = STOP;
  input vacuum: bool = false;
  input offer: Wp = NONE;
  output wp: Wp = NONE;
  output to_storage: bool = false;
  output event took;
  output event released;
  continuous pos: [0 .. 100] = 100;   // the start: waiting at the unloading position
  grid pos 20;
  region motion {
    initial Still;
    state Still {
      on [cmd == TO_STORAGE && pos > 0] -> choice { [wp == HEAVY] -> BackwardHeavy; else -> Backward; };
      on [cmd == TO_UNLOAD && pos < 100] -> choice { [wp == HEAVY] -> ForwardHeavy; else -> Forward; };
    }
    state Forward {
      der(pos) = 2;
      on [cmd != TO_UNLOAD] -> Still;
      on [pos >= 100] -> Still;
    }
    state ForwardHeavy {
      der(pos) = 0.5;
      on [cmd != TO_UNLOAD] -> Still;
      on [pos >= 100] -> Still;
    }
    state Backward {
      der(pos) = -2;
      entry { to_storage = true; }
      exit { to_storage = false; }
      on [cmd != TO_STORAGE] -> Still;
      on [pos <= 0] -> Still;
    }
    state BackwardHeavy {
      der(pos) = -0.5;
      entry { to_storage = true; }
      exit { to_storage = false; }
      on [cmd != TO_STORAGE] -> Still;
      on [pos <= 0] -> Still;
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

// D-Transfer: a DC motor. Its speed profile (ours, README.md), measured from the start of each
// motion (always at an end of the stroke): start-up at half speed for the first 5 % (5 s
// empty or light, 20 s heavy), cruise at full speed over the 90 % between (45 s, 180 s),
// slow-down at half speed over the last 5 %. Full speeds as for the L-Transfer.
plant chart DTransfer implements TransferDrive {
  input cmd: Move = STOP;
  input vacuum: bool = false;
  input offer: Wp = NONE;
  output wp: Wp = NONE;
  output to_storage: bool = false;
  output event took;
  output event released;
  continuous pos: [0 .. 100] = 100;   // the start: waiting at the unloading position
  grid pos 20;
  region motion {
    initial Still;
    state Still {
      on [cmd == TO_STORAGE && pos > 0] -> choice { [wp == HEAVY] -> BackwardHeavy; else -> Backward; };
      on [cmd == TO_UNLOAD && pos < 100] -> choice { [wp == HEAVY] -> ForwardHeavy; else -> Forward; };
    }
    state Forward {
      der(pos) = profile(1 for 5 s, 2 for 45 s, 1);
      on [cmd != TO_UNLOAD] -> Still;
      on [pos >= 100] -> Still;
    }
    state ForwardHeavy {
      der(pos) = profile(0.25 for 20 s, 0.5 for 180 s, 0.25);
      on [cmd != TO_UNLOAD] -> Still;
      on [pos >= 100] -> Still;
    }
    state Backward {
      der(pos) = profile(-1 for 5 s, -2 for 45 s, -1);
      entry { to_storage = true; }
      exit { to_storage = false; }
      on [cmd != TO_STORAGE] -> Still;
      on [pos <= 0] -> Still;
    }
    state BackwardHeavy {
      der(pos) = profile(-0.25 for 20 s, -0.5 for 180 s, -0.25);
      entry { to_storage = true; }
      exit { to_storage = false; }
      on [cmd != TO_STORAGE] -> Still;
      on [pos <= 0] -> Still;
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

// The Transfer station: its controller and its drive (a slot: `LTransfer` or `DTransfer`).
component Transfer {
  input run: bool;            // the panel's RUN
  input allow_right: bool;    // the Storage's interlock
  input offer: Wp;            // the workpiece the Feeder offers at the pick-up position
  output event took;          // the suction took it (to the Feeder)
  output event taken;         // TAKEN (to the Storage's controller)
  instance tc: TransferController;
  instance tr: TransferDrive;        // the L-Transfer or the D-Transfer
  connect run -> tc.run;
  connect allow_right -> tc.allow_right;
  connect offer -> tr.offer;
  connect tr.took -> took;
  connect tc.taken -> taken;
  connect tr.pos -> tc.pos;
  connect tr.took -> tc.took;
  connect tr.released -> tc.released;
  connect tc.cmd -> tr.cmd;
  connect tc.vacuum -> tr.vacuum;
  order tc, tr;
}
