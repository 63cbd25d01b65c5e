// The collision of the faulty interlock for each ordering of two workpieces (README.md,
// "Which orderings collide"): the station of station.sc, with the faulty Storage controller
// and the ideal HOME_SENSOR, its magazine holding exactly two workpieces of the types the
// configuration names (first, second). `no_collision` is violated only where a light one is
// followed by a heavy one (lh_L, lh_D) and proved for ll, hl and hh.
import "station.sc";

system WDSOrderings {
  instance s: Station;

  // START from tick 1 on: when START is pressed only shifts the whole run, and pinning it
  // leaves one run per configuration (the SAT engines then decide each at once).
  assume s.pn.start;

  configuration ll_L { s.st.mag = Magazine(sequence = Order.LL); s.st.stc = StorageControllerEarlyAllow; s.tx.tr = LTransfer; s.st.hs = Sensor; }
  configuration ll_D { s.st.mag = Magazine(sequence = Order.LL); s.st.stc = StorageControllerEarlyAllow; s.tx.tr = DTransfer; s.st.hs = Sensor; }
  configuration lh_L { s.st.mag = Magazine(sequence = Order.LH); s.st.stc = StorageControllerEarlyAllow; s.tx.tr = LTransfer; s.st.hs = Sensor; }
  configuration lh_D { s.st.mag = Magazine(sequence = Order.LH); s.st.stc = StorageControllerEarlyAllow; s.tx.tr = DTransfer; s.st.hs = Sensor; }
  configuration hl_L { s.st.mag = Magazine(sequence = Order.HL); s.st.stc = StorageControllerEarlyAllow; s.tx.tr = LTransfer; s.st.hs = Sensor; }
  configuration hl_D { s.st.mag = Magazine(sequence = Order.HL); s.st.stc = StorageControllerEarlyAllow; s.tx.tr = DTransfer; s.st.hs = Sensor; }
  configuration hh_L { s.st.mag = Magazine(sequence = Order.HH); s.st.stc = StorageControllerEarlyAllow; s.tx.tr = LTransfer; s.st.hs = Sensor; }
  configuration hh_D { s.st.mag = Magazine(sequence = Order.HH); s.st.stc = StorageControllerEarlyAllow; s.tx.tr = DTransfer; s.st.hs = Sensor; }

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
}
