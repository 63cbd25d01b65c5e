// fam_system2.sc — master + 2 FAMs on one LIN bus (App. A, C, D; ch. 6). The closed loop
// `FamBus(N)` (the FAM, the LIN layer, the controllers, the bus and the environment) is in
// lib/bus.sc; this file chooses N = 2 and the processing budget, and states the properties.
import "lib/modulus.sc";
import "lib/bus.sc";

const BUDGET: int = 10;    // ch. 5.4: controller steps between a response and the next request

// The properties are stated for slave 0 (the slaves are symmetric up to their slot in the
// schedule).
system FamSystem2 {
  instance net: FamBus(2);
  invariant fam_stall_blocks_run:
    !(in(net.fam[0].stallHandler.stallMode) && in(net.fam[0].moveHandler.running))
    assuming net.fam[0].runMode != FAILURE_RUN;
  invariant fam_failure_blocks_run:
    !(in(net.fam[0].failureHandler.failure) && in(net.fam[0].moveHandler.running))
    assuming net.fam[0].runMode != FAILURE_RUN;
  invariant fam_actualpos_in_range: net.fam[0].actualPos >= 0 && net.fam[0].actualPos <= 4095;
  invariant master_no_normal_run_on_failure:
    !(net.bus.reqSel == 1 && net.ctrl[0].runMode == NORMAL_RUN && (net.ctrl[0].rFail & MAJOR) != 0);
  invariant master_failure_before_stall:
    !(net.bus.reqSel == 1 && net.ctrl[0].runMode == STOP_STALL && (net.ctrl[0].rFail & MAJOR) != 0);
  invariant master_outputs_in_range: net.ctrl[0].targetPos >= 0 && net.ctrl[0].targetPos <= 4095;
  invariant master_target_outside_ends_only_calibrating:
    inRange(net.ctrl[0].targetPos, net.ctrl[0].endPos1) || net.ctrl[0].phase == CALIB;
}
