// Configurations that swap a composite component and a slot inside one (docs/components.md).
// The slot `axis` takes the component Feeder (a cylinder with a front sensor slot and a rear
// sensor) or QuickFeeder; inside Feeder, the slot `axis.front` takes a Sensor or a sensor
// stuck at false. By hand: with `normal` and `quick` the front sensor fires, so ctrl pulls;
// with `stuck` it never fires and ctrl pushes forever (`pulls` unreachable, `settles` violated).

interface Presence {
  input pos: int[0..3];
  output hit: bool;
}

interface Axis {
  input event go;
  input event back;
  output extended: bool;
  output retracted: bool;
}

chart Cylinder {
  input event go;
  input event back;
  output pos: int[0..3] = 0;
  initial Idle;
  state Idle { on go [pos < 3] / { pos = pos + 1; }; on back [pos > 0] / { pos = pos - 1; }; }
}

chart Sensor(at: int[0..3] = 3) implements Presence {
  input pos: int[0..3] = 0;
  output hit: bool = false;
  initial S;
  state S { entry { hit = pos == at; } during { hit = pos == at; } }
}

chart Stuck implements Presence {
  input pos: int[0..3] = 0;
  output hit: bool = false;
  initial S;
  state S;
}

chart Toggle {
  input event go;
  input event back;
  output out: bool = false;
  output home: bool = true;
  initial In;
  state In { on go / { out = true; home = false; } -> Out; }
  state Out { on back / { out = false; home = true; } -> In; }
}

chart Controller {
  input extended: bool = false;
  input retracted: bool = false;
  output event go;
  output event back;
  initial Push;
  state Push { entry { raise go; } during { raise go; } on [extended] -> Pull; }
  state Pull { entry { raise back; } during { raise back; } on [retracted] -> Push; }
}

component Feeder implements Axis {
  input event go;
  input event back;
  output extended: bool;
  output retracted: bool;
  instance cyl: Cylinder;
  instance front: Presence;
  instance rear: Sensor(0);
  connect go -> cyl.go;
  connect back -> cyl.back;
  connect cyl.pos -> front.pos;
  connect cyl.pos -> rear.pos;
  connect front.hit -> extended;
  connect rear.hit -> retracted;
}

component QuickFeeder implements Axis {
  input event go;
  input event back;
  output extended: bool;
  output retracted: bool;
  instance t: Toggle;
  connect go -> t.go;
  connect back -> t.back;
  connect t.out -> extended;
  connect t.home -> retracted;
}

system Line {
  instance axis: Axis;
  instance ctrl: Controller;
  connect ctrl.go -> axis.go;
  connect ctrl.back -> axis.back;
  connect axis.extended -> ctrl.extended;
  connect axis.retracted -> ctrl.retracted;
  configuration normal {
    axis = Feeder;
    axis.front = Sensor(3);
  }
  configuration stuck {
    axis = Feeder;
    axis.front = Stuck;
  }
  configuration quick {
    axis = QuickFeeder;
  }
  reachable pulls: in(ctrl.Pull);
  invariant never_both: !(axis.extended && axis.retracted);
  respond settles: ctrl.go => ctrl.extended within 8;
}
