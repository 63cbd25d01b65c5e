// The Storage: its controller, in a correct and a faulty version behind one interface, and
// the composite `Storage` (magazine, Feeder, HOME_SENSOR, controller) that wds.sc and
// orderings.sc share. The controller implements the interlock with the Transfer on its
// right: ALLOW_RIGHT lets the Transfer come to the pick-up position; TAKEN says the Transfer
// has sucked the workpiece off.
import "common.sc";
import "sensors.sc";
import "magazine.sc";
import "feeder.sc";

interface StorageControl {
  input run: bool;          // the panel's RUN
  input present: bool;      // the magazine's presence sensor: a workpiece in front of the pusher
  input home: bool;         // HOME_SENSOR: the Feeder retracted ([0, 5] %)
  input extended: bool;     // END_SENSOR: the Feeder extended ([95, 100] %)
  input event taken;        // the Transfer took the workpiece
  output extend: bool;      // the Feeder's valve
  output allow_right: bool; // ALLOW_RIGHT
}

// Correct: ALLOW_RIGHT is raised when the workpiece arrives at the pick-up position.
chart StorageController implements StorageControl {
  input run: bool = false;
  input present: bool = false;
  input home: bool = false;
  input extended: bool = false;
  input event taken;
  output extend: bool = true;        // the start: the first workpiece waits in the extended Feeder
  output allow_right: bool = true;
  initial Delivered;
  state Delivered {
    on taken / { allow_right = false; extend = false; } -> Retracting;
  }
  state Retracting {
    on [run && home && present] / { extend = true; } -> Pushing;
  }
  state Pushing {
    on [extended] / { allow_right = true; } -> Delivered;
  }
}

// Faulty: ALLOW_RIGHT is raised when the Feeder starts pushing, not when the workpiece arrives.
chart StorageControllerEarlyAllow implements StorageControl {
  input run: bool = false;
  input present: bool = false;
  input home: bool = false;
  input extended: bool = false;
  input event taken;
  output extend: bool = true;
  output allow_right: bool = true;
  initial Delivered;
  state Delivered {
    on taken / { allow_right = false; extend = false; } -> Retracting;
  }
  state Retracting {
    on [run && home && present] / { extend = true; allow_right = true; } -> Pushing;
  }
  state Pushing {
    on [extended] -> Delivered;
  }
}

// The Storage station: the magazine drops workpieces in front of the Feeder, the Feeder
// pushes them to the pick-up position, its home range predicate reaches the controller
// through HOME_SENSOR (a slot: `Sensor` or `Sensor_with_Fault`), its end one directly
// (END_SENSOR). The controller is a slot too (correct or faulty); a configuration binds both
// by path (`s.st.stc = StorageController;`) and may give the magazine its sequence.
component Storage {
  input run: bool;           // the panel's RUN
  input event taken;         // TAKEN, from the Transfer's controller
  input event picked;        // the Transfer's suction took the offered workpiece
  output allow_right: bool;  // ALLOW_RIGHT
  output offer: Wp;          // the workpiece at the pick-up position
  instance mag: Magazine;
  instance hs: PositionSensor;       // HOME_SENSOR over the Feeder's [0, 5] %
  instance stc: StorageControl;      // the correct or the faulty interlock
  instance f: Feeder;
  connect run -> stc.run;
  connect taken -> stc.taken;
  connect picked -> f.taken;
  connect stc.allow_right -> allow_right;
  connect f.offer -> offer;
  connect f.pos -> mag.pusher_pos;
  connect f.wp -> mag.pusher_wp;
  connect f.took -> mag.took;
  connect f.home -> hs.raw;
  connect mag.present -> stc.present;
  connect hs.detected -> stc.home;
  connect f.extended -> stc.extended;
  connect stc.extend -> f.extend;
  connect mag.first -> f.first;
  connect mag.slot -> f.slot;
  order mag, hs, stc, f;
}
