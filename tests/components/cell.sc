// A two-level composite (docs/components.md): Cell = ctrl + Storage, Storage = Magazine +
// Feeder, Feeder = Cylinder + two Sensors. `cell_flat.sc` is the same system flattened by
// hand (instances named with `_` for `.`); both give the same traces, verdicts and state
// counts (crates/cli/tests/composites.rs).

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

component Feeder {
  input event go;
  input event back;
  input event hold;
  output pos: int[0..3];
  output extended: bool;
  output retracted: bool;
  instance cyl: Cylinder;
  instance front: Sensor(3);
  instance rear: Sensor(0);
  connect go -> cyl.go;
  connect back -> cyl.back;
  connect hold -> cyl.hold;
  connect cyl.pos -> front.pos;
  connect cyl.pos -> rear.pos;
  connect cyl.pos -> pos;
  connect front.hit -> extended;
  connect rear.hit -> retracted;
  order cyl, front, rear;
  invariant sensors_exclusive: !(front.hit && rear.hit);
}

component Storage {
  input event go;
  input event back;
  input event take;
  input event hold; // free in Cell: one event for the feeder and the magazine
  output extended: bool;
  output retracted: bool;
  output event empty;
  instance feeder: Feeder;
  instance magazine: Magazine;
  connect go -> feeder.go;
  connect back -> feeder.back;
  connect take -> magazine.take;
  connect hold -> feeder.hold;
  connect hold -> magazine.hold;
  connect feeder.extended -> extended;
  connect feeder.retracted -> retracted;
  connect magazine.empty -> empty;
}

system Cell {
  instance ctrl: Controller;
  instance storage: Storage;
  connect ctrl.go -> storage.go;
  connect ctrl.back -> storage.back;
  connect ctrl.take -> storage.take;
  connect storage.extended -> ctrl.extended;
  connect storage.retracted -> ctrl.retracted;
  connect storage.empty -> ctrl.empty;
  order storage, ctrl;
  // Once the magazine is empty the cylinder never comes back home (pos 0): the observer
  // reads instances inside components by path.
  observer EmptyStaysOut {
    initial Loaded;
    state Loaded { on [in(storage.magazine.Empty)] -> Watching; }
    state Watching { on [storage.feeder.cyl.pos == 0] -> error; }
    state error;
  }
  reachable done: in(ctrl.Done);
  invariant pos_bounded: storage.feeder.pos <= 3;
  reachable half_way: storage.feeder.cyl.pos == 2 && storage.magazine.count == 1;
  invariant never_empty_extended: !(storage.magazine.count == 0 && storage.extended);
}
