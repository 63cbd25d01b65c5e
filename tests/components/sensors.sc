// A sensor slot with two swappable charts (docs/components.md), verified in two
// configurations. The alarm must follow the reading: with `ideal`, present = (raw > 3) in
// the same tick, so `alarm_follows` holds; with `faulty` the sensor may stick at false (raw = 4,
// stuck), with `sensitive` it reports raw = 1 as present: both violate it in tick 0.
interface PresenceSensor {
  input raw: int[0..9];
  output present: bool;
}

chart Sensor(threshold: int[0..9] = 3) implements PresenceSensor {
  input raw: int[0..9] = 0;
  output present: bool = false;
  initial S;
  state S { entry { present = raw > threshold; } during { present = raw > threshold; } }
}

chart StuckSensor implements PresenceSensor {
  input raw: int[0..9] = 0;
  input stuck: bool = false;
  output present: bool = false;
  initial S;
  state S { entry { present = raw > 3 && !stuck; } during { present = raw > 3 && !stuck; } }
}

chart Alarm {
  input seen: bool = false;
  output alarm: bool = false;
  initial A;
  state A { entry { alarm = seen; } during { alarm = seen; } }
}

system Plant {
  instance s: PresenceSensor;
  instance a: Alarm;
  connect s.present -> a.seen;
  order s, a;
  configuration ideal {
    s = Sensor;
  }
  configuration faulty {
    s = StuckSensor;
  }
  configuration sensitive {
    s = Sensor(threshold = 0);
  }
  invariant alarm_follows: a.alarm == (s.raw > 3);
  reachable alarm_on: a.alarm;
}
