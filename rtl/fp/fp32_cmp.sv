// IEEE-754 binary32 comparator: lt = a < b, le = a <= b, eq = a == b, as C++ compares floats
// (every relation false when an operand is a NaN; -0 == +0). One pipeline stage (the TM's
// comparator latency): the relations of operands presented in cycle c (en high) are on the
// outputs in cycle c + 1.
module fp32_cmp (
    input  logic        clk,
    input  logic        en,
    input  logic [31:0] a,
    input  logic [31:0] b,
    output logic        lt,
    output logic        le,
    output logic        eq
);
  import fp32_pkg::*;
  always_ff @(posedge clk) begin
    if (en) begin
      lt <= fp32_pkg::lt(a, b);
      le <= fp32_pkg::le(a, b);
      eq <= fp32_pkg::eq(a, b);
    end
  end
endmodule
