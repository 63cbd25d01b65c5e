// lin_vectors.sc — the LIN encoder/decoder functions with a harness chart (tests:
// crates/cli/tests/fam.rs).
import "lib/modulus.sc";
import "lib/fam.sc";
import "lib/lin.sc";
import "lib/master.sc";

// ---------------------------------------------------------------------------------------
// A harness for the LIN encoder: every output is a pure function of this tick's inputs
// (outputs are written from tick 1 on). The test suite feeds it hand-computed byte vectors.
chart LinVectors {
  input id: int[0..63] = 0;
  input mode: RunMode = STOP_STALL;
  input swap: bool = false;
  input target: int[0..4095] = 0;
  input notCalib: bool = false;
  input stall: bool = false;
  input dir: bool = false;
  input run: bool = false;
  input pos: int[0..4095] = 0;
  input fail: int[0..255] = 0;
  output ident: int[0..255] = 0;
  output identOk: bool = false;
  output rq1: int[0..255] = 0;
  output rq2: int[0..255] = 0;
  output rqCk: int[0..255] = 0;
  output rs1: int[0..255] = 0;
  output rs2: int[0..255] = 0;
  output rs5: int[0..255] = 0;
  output rsCk: int[0..255] = 0;
  output rqSumOk: bool = false;           // data + checksum add up to 0xFF
  output rqCorruptOk: bool = false;       // the same with bit 0 of DB2 flipped
  output rsSumOk: bool = false;           // the master's check of the response
  output decMode: RunMode = STOP_STALL;   // what FamPort decodes from the request
  output decSwap: bool = false;
  output decTarget: int[0..4095] = 0;
  initial s;
  state s {
    during {
      ident = identField(id);
      identOk = parityOk(ident);
      rq1 = reqDb1(mode, swap, target);
      rq2 = reqDb2(target);
      rqCk = checksum2(rq1, rq2);
      rs1 = rspDb1(notCalib, stall, dir, run, pos);
      rs2 = rspDb2(pos);
      rs5 = fail;
      rsCk = checksumRsp(rs1, rs2, rs5);
      rqSumOk = addc(addc(rq1, rq2), rqCk) == 0xFF;
      rqCorruptOk = addc(addc(rq1, corruptByte(rq2, true)), rqCk) == 0xFF;
      rsSumOk = rspOk(rs1, rs2, rs5, rsCk);
      decMode = modeOf(rq1 >> 5);
      decSwap = (rq1 & 0x10) != 0;
      decTarget = ((rq1 & 0x0F) << 8) | rq2;
    }
  }
}
