// IEEE-754 binary32 helpers shared by the FP units and the fused pipelines: classification,
// ordered comparison, and the one normalise-and-round step (round to nearest even, gradual
// underflow, overflow to infinity). Every function is combinational; the units put their
// pipeline registers around them. docs/rtl-cosim.md describes the arithmetic.
package fp32_pkg;
  // The classification functions take a whole float and look at some of its fields, and a
  // unit that uses only some of the helpers leaves the others unused: both are intended.
  /* verilator lint_off UNUSEDSIGNAL */
  /* verilator lint_off UNUSEDPARAM */

  // The NaN every unit produces (the host's may differ in sign and payload; only "is a NaN"
  // is part of the contract, docs/rtl-cosim.md).
  localparam logic [31:0] CANONICAL_NAN = 32'h7FC0_0000;

  function automatic logic is_nan(input logic [31:0] x);
    return (x[30:23] == 8'hFF) && (x[22:0] != 23'd0);
  endfunction

  function automatic logic is_inf(input logic [31:0] x);
    return (x[30:23] == 8'hFF) && (x[22:0] == 23'd0);
  endfunction

  function automatic logic is_zero(input logic [31:0] x);
    return x[30:0] == 31'd0;
  endfunction

  // Finite: neither inf nor NaN (what intersect.h's x - x == 0 decides).
  function automatic logic is_finite(input logic [31:0] x);
    return x[30:23] != 8'hFF;
  endfunction

  // a < b, false when either is a NaN; -0 and +0 are equal.
  function automatic logic lt(input logic [31:0] a, input logic [31:0] b);
    logic r;
    if (is_nan(a) || is_nan(b)) r = 1'b0;
    else if (is_zero(a) && is_zero(b)) r = 1'b0;
    else if (a[31] != b[31]) r = a[31];
    else if (a[31] == 1'b0) r = a[30:0] < b[30:0];
    else r = a[30:0] > b[30:0];
    return r;
  endfunction

  // a == b, false when either is a NaN; -0 == +0.
  function automatic logic eq(input logic [31:0] a, input logic [31:0] b);
    logic r;
    if (is_nan(a) || is_nan(b)) r = 1'b0;
    else if (is_zero(a) && is_zero(b)) r = 1'b1;
    else r = a == b;
    return r;
  endfunction

  function automatic logic le(input logic [31:0] a, input logic [31:0] b);
    return lt(a, b) || eq(a, b);
  endfunction

  // intersect.h: max_ignore_nan(m, x) = x > m ? x : m, min_ignore_nan(m, x) = x < m ? x : m.
  function automatic logic [31:0] max_ignore_nan(input logic [31:0] m, input logic [31:0] x);
    return lt(m, x) ? x : m;
  endfunction

  function automatic logic [31:0] min_ignore_nan(input logic [31:0] m, input logic [31:0] x);
    return lt(x, m) ? x : m;
  endfunction

  // Position of the most significant set bit (0 when s == 0).
  function automatic logic [6:0] lead_one(input logic [63:0] s);
    logic [6:0] pos;
    pos = 7'd0;
    for (int i = 0; i < 64; i++) begin
      if (s[i]) pos = 7'(i);
    end
    return pos;
  endfunction

  // The binary32 nearest (ties to even) to (-1)^sign * s * 2^f, for s != 0. Normal results
  // get the 24-bit significand s * 2^(-rs); below 2^-126 the exponent is held at the
  // subnormal one and the significand shifts right further (gradual underflow). A carry out of
  // the rounded significand moves into the exponent field by the addition itself, and an
  // exponent field of 255 or more is an overflow to infinity.
  function automatic logic [31:0] round_pack(input logic sign, input logic [63:0] s,
                                             input logic signed [15:0] f);
    logic signed [15:0] rb;       // biased exponent of the leading one
    logic signed [15:0] rbe;      // biased exponent of the result (at least 1)
    logic signed [15:0] rs;       // right shift that leaves a 24-bit significand
    logic [6:0] shift;
    logic [129:0] x;
    logic [63:0] sig;
    logic guard, sticky, inc;
    logic [40:0] bits;
    logic [31:0] r;
    rb = 16'(lead_one(s)) + f + 16'sd127;
    rbe = (rb < 16'sd1) ? 16'sd1 : rb;
    rs = rbe - 16'sd150 - f;
    if (rs <= 16'sd0) begin
      sig = s << 7'(-rs);
      guard = 1'b0;
      sticky = 1'b0;
    end else begin
      shift = (rs > 16'sd66) ? 7'd66 : 7'(rs);
      x = {s, 66'd0} >> shift;
      sig = x[129:66];
      guard = x[65];
      sticky = |x[64:0];
    end
    inc = guard & (sticky | sig[0]);
    bits = ({25'd0, rbe} - 41'd1) * 41'd8388608 + {1'b0, sig[39:0]} + {40'd0, inc};
    if (bits >= 41'h07F80_0000) r = {sign, 8'hFF, 23'd0};
    else r = {sign, bits[30:0]};
    return r;
  endfunction

  /* verilator lint_on UNUSEDPARAM */
  /* verilator lint_on UNUSEDSIGNAL */
endpackage
