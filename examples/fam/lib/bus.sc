// lib/bus.sc — what depends on the number of slaves N, written once for every N: the
// scheduler + master LIN driver `MasterBus(N)`, the slaves' wired-AND `SlaveBus(N)`, the fault
// environment `Env(N)` and the closed loop of master + N FAMs `FamBus(N)` (a component: its
// instances and wiring). Reads BUDGET, declared by the entry file (the controller's
// processing ticks per bus round). Import it after a modulus file (lib/modulus.sc or
// lib/thesis_modulus.sc), like lib/master.sc.

import "fam.sc";
import "lin.sc";
import "master.sc";
import "tie.sc";

// Scheduler + master LIN driver for N slaves, Fig. D.1: request slots 0..N-1, response slots
// N..2N-1, then BUDGET processing ticks. A request slot sends the header and request field of
// that slave's controller (its outputs of the previous tick); a response slot sends only the
// header. `corrupt` flips a bit of the request field.
chart MasterBus(N: int[1..5]) {
  input corrupt: bool = false;
  input rm[N]: RunMode = STOP_STALL; // controller k's request: run mode, swap, target
  input sw[N]: bool = false;
  input tp[N]: int[0..8191] = 0;
  output slot: int[0..2 * N + BUDGET - 1] = 2 * N + BUDGET - 1;
  output reqSel: int[0..5] = 0; // k+1 in slave k's request slot
  output rspSel: int[0..5] = 0; // k+1 in slave k's response slot
  output proc: bool = false;    // a processing tick
  output hIdent: int[0..255] = IDLE;
  output hB1: int[0..255] = IDLE;
  output hB2: int[0..255] = IDLE;
  output hCk: int[0..255] = IDLE;
  initial run;
  state run {
    during {
      slot = if slot + 1 >= 2 * N + BUDGET then 0 else slot + 1;
      reqSel = if slot < N then slot + 1 else 0;
      rspSel = if slot >= N && slot < 2 * N then slot - N + 1 else 0;
      proc = slot >= 2 * N;
      hIdent = IDLE;
      hB1 = IDLE;
      hB2 = IDLE;
      hCk = IDLE;
      for k in 0..N {
        if slot == k {
          hIdent = identField(reqId(k));
          hB1 = reqDb1(rm[k], sw[k], tp[k]);
          hB2 = corruptByte(reqDb2(tp[k]), corrupt);
          hCk = checksum2(reqDb1(rm[k], sw[k], tp[k]), reqDb2(tp[k]));
        }
        if slot == N + k {
          hIdent = identField(rspId(k));
        }
      }
    }
  }
}

// The slaves' side of the bus: wired-AND of the response fields (only the addressed slave
// drives it; the others send 0xFF, the identity of `&`).
chart SlaveBus(N: int[1..5]) {
  input rB1[N]: int[0..255] = IDLE;
  input rB2[N]: int[0..255] = IDLE;
  input rB5[N]: int[0..255] = IDLE;
  input rCk[N]: int[0..255] = IDLE;
  output sB1: int[0..255] = IDLE;
  output sB2: int[0..255] = IDLE;
  output sB5: int[0..255] = IDLE;
  output sCk: int[0..255] = IDLE;
  initial run;
  state run {
    during {
      sB1 = IDLE;
      sB2 = IDLE;
      sB5 = IDLE;
      sCk = IDLE;
      for k in 0..N {
        sB1 = sB1 & rB1[k];
        sB2 = sB2 & rB2[k];
        sB5 = sB5 & rB5[k];
        sCk = sCk & rCk[k];
      }
    }
  }
}

// The environment of N FAMs: one CCM value for every controller, and at most one fault per
// tick, injected into FAM `who` (or its response frame; a corrupted request frame reaches
// every slave).
enum EnvFault {
  NONE,
  STALL,
  HSL_F,
  EPM_F,
  OTF_F,
  FBF_F,
  CCF_F,
  POWER_LOSS,
  REQ_CORRUPT,
  RSP_CORRUPT,
}

chart Env(N: int[1..5]) {
  input ccmSel: int[0..2] = 0;
  input who: int[0..N - 1] = 0;
  input fault: EnvFault = NONE;
  output ccm: int[0..1000] = 0;
  output reqCorrupt: bool = false;
  output stallNow[N]: bool = false;
  output hslFault[N]: bool = false;
  output epmFault[N]: bool = false;
  output otFault[N]: bool = false;
  output fbfFault[N]: bool = false;
  output ccfFault[N]: bool = false;
  output powerLoss[N]: bool = false;
  output rspCorrupt[N]: bool = false;
  initial s;
  state s {
    during {
      ccm = ccmSel * 500;
      reqCorrupt = fault == REQ_CORRUPT;
      for k in 0..N {
        stallNow[k] = who == k && fault == STALL;
        hslFault[k] = who == k && fault == HSL_F;
        epmFault[k] = who == k && fault == EPM_F;
        otFault[k] = who == k && fault == OTF_F;
        fbfFault[k] = who == k && fault == FBF_F;
        ccfFault[k] = who == k && fault == CCF_F;
        powerLoss[k] = who == k && fault == POWER_LOSS;
        rspCorrupt[k] = who == k && fault == RSP_CORRUPT;
      }
    }
  }
}

// Master + N FAMs on one LIN bus, as in the thesis's HIL attempt (ch. 6: five FAMs). Every
// slave k has its own controller ctrl[k] (3.2) and its LIN port port[k]; the environment
// injects at most one fault per tick into one FAM. Its free inputs are env.ccmSel, env.who
// and env.fault.
component FamBus(N: int[2..5]) {
  instance bus: MasterBus(N);
  instance port[N]: FamPort;
  instance fam[N]: Fam(FAM_START);
  instance sbus: SlaveBus(N);
  instance ctrl[N]: Controller;
  instance tie: Tie(N);
  instance env: Env(N);
  // The master's header and request field reach every slave; its schedule every controller.
  connect bus.hIdent -> port[*].hIdent;
  connect bus.hB1 -> port[*].hB1;
  connect bus.hB2 -> port[*].hB2;
  connect bus.hCk -> port[*].hCk;
  connect bus.rspSel -> ctrl[*].rspSel;
  connect bus.proc -> ctrl[*].proc;
  connect env.reqCorrupt -> bus.corrupt;
  // The wired-AND response field reaches every controller.
  connect sbus.sB1 -> ctrl[*].sB1;
  connect sbus.sB2 -> ctrl[*].sB2;
  connect sbus.sB5 -> ctrl[*].sB5;
  connect sbus.sCk -> ctrl[*].sCk;
  connect tie.low -> fam[*].saveFails;
  // Slave k: its port drives its FAM, and the FAM's state goes back into the response.
  connect port[*].runMode -> fam[*].runMode;
  connect port[*].swap -> fam[*].swap;
  connect port[*].targetPos -> fam[*].targetPos;
  connect port[*].cofNow -> fam[*].cofNow;
  connect fam[*].notCalib -> port[*].notCalib;
  connect fam[*].stall -> port[*].stall;
  connect fam[*].dir -> port[*].dir;
  connect fam[*].run -> port[*].run;
  connect fam[*].actualPos -> port[*].actualPos;
  connect fam[*].failureReg -> port[*].failureReg;
  // Slave k's response onto the bus; controller k's request into the master's slot k.
  connect port[*].rB1 -> sbus.rB1[*];
  connect port[*].rB2 -> sbus.rB2[*];
  connect port[*].rB5 -> sbus.rB5[*];
  connect port[*].rCk -> sbus.rCk[*];
  connect ctrl[*].runMode -> bus.rm[*];
  connect ctrl[*].swap -> bus.sw[*];
  connect ctrl[*].targetPos -> bus.tp[*];
  connect tie.k[*] -> port[*].sna;
  connect tie.k[*] -> ctrl[*].myId;
  // The faults of FAM k, and the CCM.
  connect env.stallNow[*] -> fam[*].stallNow;
  connect env.hslFault[*] -> fam[*].hslFault;
  connect env.epmFault[*] -> fam[*].epmFault;
  connect env.otFault[*] -> fam[*].otFault;
  connect env.fbfFault[*] -> fam[*].fbfFault;
  connect env.ccfFault[*] -> fam[*].ccfFault;
  connect env.powerLoss[*] -> fam[*].powerLoss;
  connect env.rspCorrupt[*] -> ctrl[*].corrupt;
  connect env.ccm -> ctrl[*].ccm;
  order env, tie, bus, port, fam, sbus, ctrl;
}
