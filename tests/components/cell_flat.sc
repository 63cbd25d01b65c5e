// `cell.sc` flattened by hand: its component instances replaced by their instances, named
// with `_` where `cell.sc`'s paths have `.`, connections through ports wired directly, the
// free port `storage.hold` as the first inner input it feeds, read by the second, the order
// spliced (storage first: feeder's cyl, front, rear, then the magazine; then ctrl).

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
  connect ctrl.back -> storage_feeder_cyl.back;
  connect ctrl.take -> storage_magazine.take;
  connect storage_feeder_front.hit -> ctrl.extended;
  connect storage_feeder_rear.hit -> ctrl.retracted;
  connect storage_magazine.empty -> ctrl.empty;
  order storage_feeder_cyl, storage_feeder_front, storage_feeder_rear, storage_magazine, ctrl;
  invariant storage_feeder_sensors_exclusive:
    !(storage_feeder_front.hit && storage_feeder_rear.hit);
  // Once the magazine is empty the cylinder never comes back home (pos 0): the observer
  // reads instances inside components by path.
  observer EmptyStaysOut {
    initial Loaded;
    state Loaded { on [in(storage_magazine.Empty)] -> Watching; }
    state Watching { on [storage_feeder_cyl.pos == 0] -> error; }
    state error;
  }
  reachable done: in(ctrl.Done);
  invariant pos_bounded: storage_feeder_cyl.pos <= 3;
  reachable half_way: storage_feeder_cyl.pos == 2 && storage_magazine.count == 1;
  invariant never_empty_extended: !(storage_magazine.count == 0 && storage_feeder_front.hit);
}
