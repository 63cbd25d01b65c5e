// Imports a chart whose state `Never` is dead: verify must report it at the library file's
// line (tests/components/lib/latch.sc:8), not at a line of this file.
import "lib/latch.sc";

system UsesLatch {
  instance l: Latch;
  reachable latched: l.lit;
}
