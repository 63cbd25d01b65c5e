// The Storage's magazine: a stack of workpieces that drops the next one in front of the
// Feeder's pusher, by gravity, once the pusher is back home and empty. A presence sensor
// reports the workpiece in front of the pusher ("workpiece available").
import "common.sc";

// What the magazine holds: ANY is an endless stack whose types are unknown (each is a free
// input: every sequence of light and heavy workpieces); the others hold exactly two
// workpieces of the given types (first, second) and are then empty. The first lies already
// in the extended Feeder when the run starts (README.md, "The start").
enum Order { ANY, LL, LH, HL, HH }

fn type_of(heavy: bool) -> Wp = if heavy then Wp.HEAVY else Wp.LIGHT;

fn first_of(s: Order, heavy: bool) -> Wp =
  if s == Order.ANY then type_of(heavy)
  else if s == Order.HL || s == Order.HH then Wp.HEAVY
  else Wp.LIGHT;

fn second_of(s: Order, heavy: bool) -> Wp =
  if s == Order.ANY then type_of(heavy)
  else if s == Order.LH || s == Order.HH then Wp.HEAVY
  else Wp.LIGHT;

chart Magazine(sequence: Order = Order.ANY) {
  input heavy: bool = false;            // the type of the workpiece dropped in this tick (free)
  input pusher_pos: int[0..100] = 100;  // the Feeder's position
  input pusher_wp: Wp = NONE;           // the workpiece the Feeder pushes
  input event took;                     // token protocol: the Feeder took the workpiece
  output first: Wp = LIGHT;             // the workpiece in the Feeder at the start
  output slot: Wp = NONE;               // buffer of size 1: the workpiece in front of the pusher
  output present: bool = false;         // the presence sensor
  local left: bool = true;              // a fixed sequence still holds its second workpiece
  initial Stocked / { first = first_of(sequence, heavy); };
  state Stocked {
    on took / { slot = NONE; present = false; };
    on [slot == NONE && pusher_pos == 0 && pusher_wp == NONE && (sequence == Order.ANY || left)]
      / { slot = second_of(sequence, heavy); present = true; left = false; };
  }
}
