// liveness/linear_drive_live.sc — liveness of the linear drive (issue 16). The charts, constants
// and tick are linear_drive.sc's, imported (docs/components.md); this file states the temporal
// properties of the same closed loop.
import "../linear_drive.sc" { Controller, Drive };

system LinearDriveLive {
  instance ctrl: Controller;
  instance drive: Drive;
  connect ctrl.U -> drive.U;
  connect drive.x -> ctrl.x;
  order ctrl, drive;
  assume !(ctrl.Run && ctrl.Halt);

  // §2.1: after Run (which enters Go; Run in tick 0 is not seen, R1) the drive eventually
  // reaches each end position — unless Halt is given
  // again (the operator may stop it at any time), so the property allows for a later Halt.
  ltl run_reaches_left: G((ctrl.Run && in(ctrl.Go)) => F(drive.x < LIMIT_LEFT || ctrl.Halt));
  ltl run_reaches_right: G((ctrl.Run && in(ctrl.Go)) => F(drive.x > LIMIT_RIGHT || ctrl.Halt));
  // Without the Halt escape the property fails: Halt right after Run stops the drive.
  ltl run_reaches_left_always: G((ctrl.Run && in(ctrl.Go)) => F drive.x < LIMIT_LEFT);
  // The controller can always be brought back to Stop, and from there restarted.
  ctl can_stop: AG EF in(ctrl.Stop);
  nonblocking can_run: in(ctrl.Go);
}
