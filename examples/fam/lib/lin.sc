// lib/lin.sc — the LIN layer: frames, ident parity, checksums and the FAM's communication
// superstate `FamPort`. Uses RunMode and the FAM's constants (lib/fam.sc, import it first).

// =======================================================================================
// The LIN layer (thesis App. A, C.2): frames, ident parity, checksum; the FAM's
// communication superstate (Fig. 3.1, 3.2) as the chart `FamPort`.
// =======================================================================================
//
// Frame model. One tick of the bus carries one frame: the master's header (ident field) and
// either the master's REQUEST field (2 data bytes, Table C.1) or the addressed slave's RESPONSE
// field (Table C.5), each followed by its checksum. Bit timing (sync break, sync field 0x55,
// Table A.1) is below the tick and not modelled. The bus is wired-AND: an idle byte is 0xFF.
//
// Identifiers (Fig. A.5). The thesis gives no slave node addresses, so we choose: slave k
// (0..4) has REQUEST ID 2k (ID0 = 0) and RESPONSE ID 2k+1 (ID0 = 1) in ID3..ID0; the length bits
// ID5 ID4 are 00 (2 data bytes) for requests and 11 (8 data bytes) for responses: LIN 1.2 has
// no 5-byte frame, so the response carries DB1..DB5 of Table C.5 and three padding bytes 0xFF.
// DB3/DB4 (last min/max torque) are "not implemented in the FAM model" (C.2.2.2-3) and sent as
// 0xFF ("The value is set to 0xFF when the stall flag is cleared"). The constant bytes
// DB3, DB4, DB6..DB8 are not carried on the modelled bus; they enter the checksum as constants.

const IDLE: int = 0xFF;
const FAM_START: int = 4092;   // closed loop: the FAM's saved position at power-up, in the flap range

fn bit(x: int[0..255], i: int[0..7]) -> int[0..1] = (x >> i) & 1;

// Equation A.1: P0 = ID0 ^ ID1 ^ ID2 ^ ID4 (even), P1 = !(ID1 ^ ID3 ^ ID4 ^ ID5) (odd);
// the protected identifier is ID5..ID0 with P0 in bit 6 and P1 in bit 7.
fn identField(id: int[0..63]) -> int[0..255] {
  let p0 = bit(id, 0) ^ bit(id, 1) ^ bit(id, 2) ^ bit(id, 4);
  let p1 = 1 ^ (bit(id, 1) ^ bit(id, 3) ^ bit(id, 4) ^ bit(id, 5));
  return id | (p0 << 6) | (p1 << 7);
}
fn reqId(k: int[0..4]) -> int[0..63] = 2 * k;
fn rspId(k: int[0..4]) -> int[0..63] = 0x30 | (2 * k + 1);
// A received ident field is accepted only if its parity bits match (A.2.1.2).
fn parityOk(f: int[0..255]) -> bool = identField(f & 0x3F) == f;

// A.2.1.3: "ADD with Carry": the carry of each 8-bit addition is added to the LSB of the sum.
fn addc(a: int[0..255], b: int[0..255]) -> int[0..255] = if a + b > 255 then a + b - 255 else a + b;
// The checksum is the inverted sum, so that data + checksum adds up to 0xFF.
fn checksum2(d1: int[0..255], d2: int[0..255]) -> int[0..255] = 255 - addc(d1, d2);
// The response's sum runs over DB1..DB8 = d1, d2, 0xFF, 0xFF, d5, 0xFF, 0xFF, 0xFF.
fn sumRsp(d1: int[0..255], d2: int[0..255], d5: int[0..255]) -> int[0..255] =
  addc(addc(addc(addc(addc(addc(addc(d1, d2), 0xFF), 0xFF), d5), 0xFF), 0xFF), 0xFF);
fn checksumRsp(d1: int[0..255], d2: int[0..255], d5: int[0..255]) -> int[0..255] =
  255 - sumRsp(d1, d2, d5);

// Table C.2 / D.1: the run mode code in DB1_REQ bits 7..5.
fn modeCode(m: RunMode) -> int[0..7] =
  if m == STOP_STALL then 0 else if m == STOP_FAILURE then 1 else if m == NORMAL_RUN then 2
  else if m == NORMAL_RUN_FIXED_LOW then 3 else if m == FAILURE_RUN then 4
  else if m == NORMAL_RUN_LOW then 5 else if m == CLEAR_NOT_CALIB then 6 else 7;
fn modeOf(c: int[0..7]) -> RunMode =
  if c == 0 then STOP_STALL else if c == 1 then STOP_FAILURE else if c == 2 then NORMAL_RUN
  else if c == 3 then NORMAL_RUN_FIXED_LOW else if c == 4 then FAILURE_RUN
  else if c == 5 then NORMAL_RUN_LOW else if c == 6 then CLEAR_NOT_CALIB else NORMAL_RUN_HIGH;

// Table C.1: DB1_REQ = run mode (7..5) | swap (4) | target MSB (3..0); DB2_REQ = target LSB.
// Positions are masked to 12 bits (a 4096 from a faulty modulus would otherwise spill into the
// swap bit: the frame can only carry 0..4095).
fn reqDb1(m: RunMode, swap: bool, target: int[0..8191]) -> int[0..255] =
  (modeCode(m) << 5) | (if swap then 0x10 else 0) | ((target >> 8) & 0x0F);
fn reqDb2(target: int[0..8191]) -> int[0..255] = target & 0xFF;
// Table C.5/C.6: DB1_RES = NOT-CALIB (7) | STALL (6) | DIR (5) | RUN (4) | actual MSB (3..0).
fn rspDb1(notCalib: bool, stall: bool, dir: bool, run: bool, pos: int[0..8191]) -> int[0..255] =
  (if notCalib then 0x80 else 0) | (if stall then 0x40 else 0) | (if dir then 0x20 else 0)
  | (if run then 0x10 else 0) | ((pos >> 8) & 0x0F);
fn rspDb2(pos: int[0..8191]) -> int[0..255] = pos & 0xFF;

// A corrupted frame: the environment flips bit 0 of the second data byte. A single-bit error
// always changes the carry-wrapped sum, so the checksum detects it.
fn corruptByte(b: int[0..255], corrupt: bool) -> int[0..255] = if corrupt then b ^ 1 else b;

// ---------------------------------------------------------------------------------------
// The FAM's communication superstate (Fig. 3.1/3.2, C.2): listens to every header on the bus.
//  - its REQUEST ID with a good checksum: the request fields are taken over (and held: "the
//    actuator keeps the latest OK message");
//  - a header with a parity error, or its REQUEST ID with a bad checksum: COF (Table C.9 bit 3:
//    "parity error", "bit frame error" ...); "The Received message will be scrapped";
//  - its RESPONSE ID: it answers with DB1..DB5 (Table C.5) from the FAM's outputs as they were
//    at the end of the previous tick (the port runs before the FAM).
// Runs before its `Fam`, which reads runMode/swap/targetPos/cofNow in the same tick.
chart FamPort {
  input sna: int[0..4] = 0;                 // slave node address (fixed by an assume)
  input hIdent: int[0..255] = IDLE;         // master -> slaves: header and request field
  input hB1: int[0..255] = IDLE;
  input hB2: int[0..255] = IDLE;
  input hCk: int[0..255] = IDLE;
  input notCalib: bool = false;             // the FAM's response fields
  input stall: bool = false;
  input dir: bool = false;
  input run: bool = false;
  input actualPos: int[0..8191] = 0;
  input failureReg: int[0..255] = 0;
  output runMode: RunMode = STOP_STALL;     // held request fields, to the FAM
  output swap: bool = false;
  output targetPos: int[0..4095] = FAM_START;
  output cofNow: bool = false;
  output rB1: int[0..255] = IDLE;           // response field (0xFF when not addressed)
  output rB2: int[0..255] = IDLE;
  output rB5: int[0..255] = IDLE;
  output rCk: int[0..255] = IDLE;
  initial listening;
  state listening {
    during {
      cofNow = false;
      rB1 = IDLE; rB2 = IDLE; rB5 = IDLE; rCk = IDLE;
      if hIdent != IDLE && !parityOk(hIdent) {
        cofNow = true;
      } else if hIdent == identField(reqId(sna)) {
        if addc(addc(hB1, hB2), hCk) == 0xFF {
          runMode = modeOf(hB1 >> 5);
          swap = (hB1 & 0x10) != 0;
          targetPos = ((hB1 & 0x0F) << 8) | hB2;
        } else {
          cofNow = true;
        }
      } else if hIdent == identField(rspId(sna)) {
        rB1 = rspDb1(notCalib, stall, dir, run, actualPos);
        rB2 = rspDb2(actualPos);
        rB5 = failureReg;
        rCk = checksumRsp(rB1, rB2, rB5);
      }
    }
  }
}

fn b(x: bool) -> int[0..1] = if x then 1 else 0;
