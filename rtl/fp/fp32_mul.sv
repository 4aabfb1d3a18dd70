// IEEE-754 binary32 multiplier, y = a * b, round to nearest even, gradual underflow.
// Two pipeline stages (the TM's multiplier latency): stage 1 classifies the operands and forms
// the 48-bit product of the significands; stage 2 normalises and rounds (fp32_pkg::round_pack).
// The result of operands presented in cycle c (with en high) is on y in cycle c + 2.
// en low freezes both stages (a stalled pipeline keeps its contents).
// A NaN result is fp32_pkg::CANONICAL_NAN.
module fp32_mul (
    input  logic        clk,
    input  logic        en,
    input  logic [31:0] a,
    input  logic [31:0] b,
    output logic [31:0] y
);
  import fp32_pkg::*;

  // Stage 1: classification and the significand product.
  typedef enum logic [1:0] {KIND_NUMBER, KIND_ZERO, KIND_INF, KIND_NAN} kind_t;
  kind_t kind_d, kind_q;
  logic sign_d, sign_q;
  logic [47:0] prod_d, prod_q;
  logic signed [15:0] f_d, f_q;

  logic [7:0] ea, eb, ea_eff, eb_eff;
  logic [23:0] ma, mb;
  always_comb begin
    ea = a[30:23];
    eb = b[30:23];
    ea_eff = (ea == 8'd0) ? 8'd1 : ea;
    eb_eff = (eb == 8'd0) ? 8'd1 : eb;
    ma = {ea != 8'd0, a[22:0]};
    mb = {eb != 8'd0, b[22:0]};
    sign_d = a[31] ^ b[31];
    prod_d = {24'd0, ma} * {24'd0, mb};
    // value = prod * 2^(ea' - 150) * 2^(eb' - 150), with e' = max(e, 1) (subnormals)
    f_d = 16'(ea_eff) + 16'(eb_eff) - 16'sd300;
    if (is_nan(a) || is_nan(b) || (is_inf(a) && is_zero(b)) || (is_zero(a) && is_inf(b)))
      kind_d = KIND_NAN;
    else if (is_inf(a) || is_inf(b)) kind_d = KIND_INF;
    else if (is_zero(a) || is_zero(b)) kind_d = KIND_ZERO;
    else kind_d = KIND_NUMBER;
  end

  always_ff @(posedge clk) begin
    if (en) begin
      kind_q <= kind_d;
      sign_q <= sign_d;
      prod_q <= prod_d;
      f_q <= f_d;
    end
  end

  // Stage 2: normalise, round, pack.
  logic [31:0] y_d;
  always_comb begin
    case (kind_q)
      KIND_NAN: y_d = CANONICAL_NAN;
      KIND_INF: y_d = {sign_q, 8'hFF, 23'd0};
      KIND_ZERO: y_d = {sign_q, 31'd0};
      default: y_d = round_pack(sign_q, {16'd0, prod_q}, f_q);
    endcase
  end

  always_ff @(posedge clk) begin
    if (en) y <= y_d;
  end
endmodule
