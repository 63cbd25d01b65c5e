// The Workpiece Distribution Station in closed loop (README.md): the operator panel, the
// Storage and the Transfer, wired once. wds.sc (the configuration matrix) and orderings.sc
// (each ordering of two workpieces) both instantiate it as `s` and bind its slots by path.
import "common.sc";
import "panel.sc";
import "storage.sc";
import "transfer.sc";

component Station {
  instance pn: Panel;
  instance st: Storage;
  instance tx: Transfer;
  connect pn.run -> st.run;
  connect pn.run -> tx.run;
  connect st.allow_right -> tx.allow_right;
  connect st.offer -> tx.offer;
  connect tx.took -> st.picked;
  connect tx.taken -> st.taken;
  // Instance order: pn, mag, hs, stc, f, tc, tr (README.md, "The loop, tick by tick").
  order pn, st, tx;
}
