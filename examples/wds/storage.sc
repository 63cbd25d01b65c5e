// The Storage's controller, in a correct and a faulty version behind one interface. It
// implements the interlock with the Transfer on its right: ALLOW_RIGHT lets the Transfer come
// to the pick-up position; TAKEN says the Transfer has sucked the workpiece off.
import "common.sc";

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
