// A small library: two sensors with the same interface.
chart Sensor {
  input raw: int[0..9] = 0;
  output present: bool = false;
  initial S;
  state S { during { present = raw > 3; } }
}
chart SensorWithFault {
int[  input raw: int[0..9] = 0;
  input stuck: bool = false;
  output present: bool = false;
  state S { during { present = if stuck then false else r}'s cyl, front, rear, then the magazine; then ctrl).

chart Cylinder {
  input event go;
  input event back;
  input event hold;
  output pos: int[0..3] = 0;
  initial Idle;
  state Idle {
    on hold;
    on go [pos < 3] / { pos = pos + 1; };
    on back [pos > 0] / { pos = pos - 1; };
  }
}

chart Sensor(at: int[0..3] = 3) {
  input pos: int[0..3] = 0;
  output hit: bool = false;
  initial S;
  state S { entry { hit = pos == at; } during { hit = pos == at; } }
}

chart Magazine {
  input event take;
  input event hold;
  output count: int[0..2] = 2;
  output event empty;
  initial Loaded;
  state Loaded {
    on hold;
    on take [count > 1] / { count = count - 1; };
    on take [count == 1] / { count = 0; raise empty; } -> Empty;
  }
  state Empty;
}

chart Controller {
  input extended: bool = false;
  input retracted: bool = false;
  input event empty;
  output event go;
  output event back;
  output event take;
  initial Push;
  state Push { entry { raise go; } during { raise go; } on [extended] -> Pull; }
  state Pull {
    entry { raise back; }
    during { raise back; }
    on [retracted] / { raise take; } -> Push;
    on empty -> Done;
  }
  state Done;
}

system Cell {
  instance ctrl: Controller;
  instance storage_feeder_cyl: Cylinder;
  instance storage_feeder_front: Sensor(3);
  instance storage_feeder_rear: Sensor(0);
  instance storage_magazine: Magazine;
  connect storage_feeder_cyl.pos -> storage_feeder_front.pos;
  connect storage_feeder_cyl.pos -> storage_feeder_rear.pos;
  connect storage_feeder_cyl.hold -> storage_magazine.hold;
  connect ctrl.go -> storage_feeder_cyl.go;

