// The operator panel: a START button and a RUN lamp. Nothing moves before START.
import "common.sc";

chart Panel {
  input event start;
  output run: bool = false;
  initial Off;
  state Off { on start -> On; }
  state On { entry { run = true; } }
}
