// The Workpiece Distribution Station (README.md): the station of station.sc in every
// configuration of its three swappable parts — the Storage controller (correct or faulty
// interlock), the Transfer's drive (L- or D-Transfer) and HOME_SENSOR (ideal or with a
// fault) — verified against the same properties: `statecheck verify wds.sc --all-configs`.
import "station.sc";

system WDS {
  instance s: Station;

  configuration faulty_L_sensor { s.st.stc = StorageControllerEarlyAllow; s.tx.tr = LTransfer; s.st.hs = Sensor; }
  configuration faulty_L_sensor_with_fault { s.st.stc = StorageControllerEarlyAllow; s.tx.tr = LTransfer; s.st.hs = Sensor_with_Fault; }
  configuration faulty_D_sensor { s.st.stc = StorageControllerEarlyAllow; s.tx.tr = DTransfer; s.st.hs = Sensor; }
  configuration faulty_D_sensor_with_fault { s.st.stc = StorageControllerEarlyAllow; s.tx.tr = DTransfer; s.st.hs = Sensor_with_Fault; }
  configuration correct_L_sensor { s.st.stc = StorageController; s.tx.tr = LTransfer; s.st.hs = Sensor; }
  configuration correct_L_sensor_with_fault { s.st.stc = StorageController; s.tx.tr = LTransfer; s.st.hs = Sensor_with_Fault; }
  configuration correct_D_sensor { s.st.stc = StorageController; s.tx.tr = DTransfer; s.st.hs = Sensor; }
  configuration correct_D_sensor_with_fault { s.st.stc = StorageController; s.tx.tr = DTransfer; s.st.hs = Sensor_with_Fault; }

  rate s.pn.start = 0.5;

  // §VII (1): the Transfer, already in its collision area (pos <= 5 %), is there when the
  // workpiece in the Feeder enters the Feeder's collision area (pos >= 95 %).
  observer no_collision {
    local feeder_was_in: bool = true;
    initial watching;
    state watching {
      entry { feeder_was_in = s.st.f.pos >= 95; }
      on [!feeder_was_in && s.st.f.pos >= 95 && s.st.f.wp != NONE && s.tx.tr.pos <= 5] -> error;
      during { feeder_was_in = s.st.f.pos >= 95; }
    }
    state error;
  }
  // §VII (2): the Transfer never heads back to the Storage holding a workpiece while another
  // lies in the extended Feeder.
  invariant no_return_with_workpiece: !(s.tx.tr.to_storage && s.tx.tr.wp != NONE && s.st.f.wp != NONE && s.st.f.pos >= 95);
  // §VII (3): a workpiece is released only at the unloading position.
  invariant release_only_at_unloading: !s.tx.tr.released || s.tx.tr.pos == 100;
  // Workpiece progress: once the station runs, workpieces keep arriving at the unloading position.
  ltl workpiece_progress: G (s.pn.run => F s.tx.tr.released);
}
