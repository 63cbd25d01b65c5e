// The Workpiece Distribution Station in closed loop (README.md): the Storage (magazine,
// Feeder, its two end-position sensors and its controller), the Transfer (drive and
// controller) and the operator panel. Three parts are swappable, and every configuration of
// them is verified against the same properties: `statecheck verify wds.sc --all-configs`.
import "common.sc";
import "sensors.sc";
import "panel.sc";
import "magazine.sc";
import "feeder.sc";
import "storage.sc";
import "transfer.sc";

system WDS {
  instance pn: Panel;
  instance mag: Magazine;
  instance hs: PositionSensor;       // HOME_SENSOR: Sensor or Sensor_with_Fault over [0, 5] %
  instance es: Sensor(95, 100);      // END_SENSOR over [95, 100] %
  instance stc: StorageControl;      // the correct or the faulty interlock
  instance f: Feeder;
  instance tc: TransferController;
  instance tr: TransferDrive;        // the L-Transfer or the D-Transfer

  connect pn.run -> stc.run;
  connect pn.run -> tc.run;
  connect f.pos -> mag.pusher_pos;
  connect f.wp -> mag.pusher_wp;
  connect f.took -> mag.took;
  connect f.pos -> hs.pos;
  connect f.pos -> es.pos;
  connect mag.present -> stc.present;
  connect hs.detected -> stc.home;
  connect es.detected -> stc.extended;
  connect tc.taken -> stc.taken;
  connect stc.extend -> f.extend;
  connect mag.first -> f.first;
  connect mag.slot -> f.slot;
  connect tr.took -> f.taken;
  connect stc.allow_right -> tc.allow_right;
  connect tr.pos -> tc.pos;
  connect tr.took -> tc.took;
  connect tr.released -> tc.released;
  connect tc.cmd -> tr.cmd;
  connect tc.vacuum -> tr.vacuum;
  connect f.offer -> tr.offer;
  order pn, mag, hs, es, stc, f, tc, tr;

  configuration faulty_L_sensor { stc = StorageControllerEarlyAllow; tr = LTransfer; hs = Sensor(0, 5); }
  configuration faulty_L_sensor_with_fault { stc = StorageControllerEarlyAllow; tr = LTransfer; hs = Sensor_with_Fault(0, 5); }
  configuration faulty_D_sensor { stc = StorageControllerEarlyAllow; tr = DTransfer; hs = Sensor(0, 5); }
  configuration faulty_D_sensor_with_fault { stc = StorageControllerEarlyAllow; tr = DTransfer; hs = Sensor_with_Fault(0, 5); }
  configuration correct_L_sensor { stc = StorageController; tr = LTransfer; hs = Sensor(0, 5); }
  configuration correct_L_sensor_with_fault { stc = StorageController; tr = LTransfer; hs = Sensor_with_Fault(0, 5); }
  configuration correct_D_sensor { stc = StorageController; tr = DTransfer; hs = Sensor(0, 5); }
  configuration correct_D_sensor_with_fault { stc = StorageController; tr = DTransfer; hs = Sensor_with_Fault(0, 5); }

  rate pn.start = 0.5;

  // §VII (1): the Transfer, already in its collision area (pos <= 5 %), is there when the
  // workpiece in the Feeder enters the Feeder's collision area (pos >= 95 %).
  observer no_collision {
    local feeder_was_in: bool = true;
    initial watching;
    state watching {
      entry { feeder_was_in = f.pos >= 95; }
      on [!feeder_was_in && f.pos >= 95 && f.wp != NONE && tr.pos <= 5] -> error;
      during { feeder_was_in = f.pos >= 95; }
    }
    state error;
  }
  // §VII (2): the Transfer never heads back to the Storage holding a workpiece while another
  // lies in the extended Feeder.
  invariant no_return_with_workpiece: !(tr.to_storage && tr.wp != NONE && f.wp != NONE && f.pos >= 95);
  // §VII (3): a workpiece is released only at the unloading position.
  invariant release_only_at_unloading: !tr.released || tr.pos == 100;
  // Workpiece progress: once the station runs, workpieces keep arriving at the unloading position.
  ltl workpiece_progress: G (pn.run => F tr.released);
}
