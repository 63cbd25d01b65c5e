// The collision of the faulty interlock for each ordering of two workpieces (README.md,
// "Which orderings collide"): the magazine holds exactly two workpieces, of the types the
// configuration names (first, second), so `no_collision` is violated only where a light one
// is followed by a heavy one (lh_L, lh_D) and proved for ll, hl and hh. The wiring is that of
// wds.sc (the faulty Storage controller, the ideal HOME_SENSOR).
import "common.sc";
import "sensors.sc";
import "panel.sc";
import "magazine.sc";
import "feeder.sc";
import "storage.sc";
import "transfer.sc";

system WDSOrderings {
  instance pn: Panel;
  instance mag: Magazine;            // each configuration fixes its two workpieces
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

  // START from tick 1 on: when START is pressed only shifts the whole run, and pinning it
  // leaves one run per configuration (the SAT engines then decide each at once).
  assume pn.start;

  configuration ll_L { mag = Magazine(sequence = Order.LL); stc = StorageControllerEarlyAllow; tr = LTransfer; hs = Sensor(0, 5); }
  configuration ll_D { mag = Magazine(sequence = Order.LL); stc = StorageControllerEarlyAllow; tr = DTransfer; hs = Sensor(0, 5); }
  configuration lh_L { mag = Magazine(sequence = Order.LH); stc = StorageControllerEarlyAllow; tr = LTransfer; hs = Sensor(0, 5); }
  configuration lh_D { mag = Magazine(sequence = Order.LH); stc = StorageControllerEarlyAllow; tr = DTransfer; hs = Sensor(0, 5); }
  configuration hl_L { mag = Magazine(sequence = Order.HL); stc = StorageControllerEarlyAllow; tr = LTransfer; hs = Sensor(0, 5); }
  configuration hl_D { mag = Magazine(sequence = Order.HL); stc = StorageControllerEarlyAllow; tr = DTransfer; hs = Sensor(0, 5); }
  configuration hh_L { mag = Magazine(sequence = Order.HH); stc = StorageControllerEarlyAllow; tr = LTransfer; hs = Sensor(0, 5); }
  configuration hh_D { mag = Magazine(sequence = Order.HH); stc = StorageControllerEarlyAllow; tr = DTransfer; hs = Sensor(0, 5); }

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
}
