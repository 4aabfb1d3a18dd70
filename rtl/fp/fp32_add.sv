// IEEE-754 binary32 adder/subtractor, y = a + b (sub = 0) or a - b (sub = 1), round to
// nearest even, gradual underflow. a - b is a + (-b) in every case, signed zeros included.
// Two pipeline stages (the TM's adder latency): stage 1 orders the operands by magnitude,
// aligns the smaller one (26 bits below the larger one's last significand bit, the rest
// collected in a sticky bit) and adds or subtracts; stage 2 normalises and rounds
// (fp32_pkg::round_pack). The result of operands presented in cycle c (en high) is on y in
// cycle c + 2; en low freezes both stages. A NaN result is fp32_pkg::CANONICAL_NAN.
module fp32_add (
    input  logic        clk,
    input  logic        en,
    input  logic [31:0] a,
    input  logic [31:0] b,
    input  logic        sub,
    output logic [31:0] y
);
  import fp32_pkg::*;

  typedef enum logic [1:0] {KIND_NUMBER, KIND_INF, KIND_NAN} kind_t;
  kind_t kind_d, kind_q;
  logic sign_d, sign_q;          // sign of the larger operand (or of the infinity)
  logic zero_sign_d, zero_sign_q; // sign of an exact zero sum
  logic [50:0] sum_d, sum_q;
  logic signed [15:0] f_d, f_q;

  logic [31:0] bb, lrg, sml;
  logic [7:0] e_lrg, e_sml, d;
  logic [23:0] m_lrg, m_sml;
  logic [6:0] shift;
  logic [101:0] aligned;
  logic [49:0] sml_al;
  always_comb begin
    bb = {b[31] ^ sub, b[30:0]};
    if (bb[30:0] > a[30:0]) begin
      lrg = bb;
      sml = a;
    end else begin
      lrg = a;
      sml = bb;
    end
    e_lrg = (lrg[30:23] == 8'd0) ? 8'd1 : lrg[30:23];
    e_sml = (sml[30:23] == 8'd0) ? 8'd1 : sml[30:23];
    m_lrg = {lrg[30:23] != 8'd0, lrg[22:0]};
    m_sml = {sml[30:23] != 8'd0, sml[22:0]};
    d = e_lrg - e_sml;
    shift = (d > 8'd52) ? 7'd52 : 7'(d);
    aligned = {m_sml, 26'd0, 52'd0} >> shift;
    sml_al = {aligned[101:53], aligned[52] | (|aligned[51:0])};
    if (lrg[31] == sml[31]) sum_d = {1'b0, m_lrg, 26'd0} + {1'b0, sml_al};
    else sum_d = {1'b0, m_lrg, 26'd0} - {1'b0, sml_al};
    sign_d = lrg[31];
    // An exact zero: -0 only for (-0) + (-0); +0 for x + (-x) (round to nearest).
    zero_sign_d = lrg[31] & sml[31];
    // value = sum * 2^(e_lrg - 150 - 26)
    f_d = 16'(e_lrg) - 16'sd176;
    if (is_nan(a) || is_nan(bb) || (is_inf(a) && is_inf(bb) && (a[31] != bb[31])))
      kind_d = KIND_NAN;
    else if (is_inf(a) || is_inf(bb)) kind_d = KIND_INF;
    else kind_d = KIND_NUMBER;
    if (is_inf(a)) sign_d = a[31];
    else if (is_inf(bb)) sign_d = bb[31];
  end

  always_ff @(posedge clk) begin
    if (en) begin
      kind_q <= kind_d;
      sign_q <= sign_d;
      zero_sign_q <= zero_sign_d;
      sum_q <= sum_d;
      f_q <= f_d;
    end
  end

  logic [31:0] y_d;
  always_comb begin
    case (kind_q)
      KIND_NAN: y_d = CANONICAL_NAN;
      KIND_INF: y_d = {sign_q, 8'hFF, 23'd0};
      default:
        if (sum_q == 51'd0) y_d = {zero_sign_q, 31'd0};
        else y_d = round_pack(sign_q, {13'd0, sum_q}, f_q);
    endcase
  end

  always_ff @(posedge clk) begin
    if (en) y <= y_d;
  end
endmodule
