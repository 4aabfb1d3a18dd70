// Running minimum / maximum of intersect.h (docs/numerics.md, "NaN rules of min and max"):
// max = 1: y = max_ignore_nan(m, x) = x > m ? x : m; max = 0: y = min_ignore_nan(m, x) =
// x < m ? x : m. A NaN candidate x never replaces m, a NaN m stays, and equal values
// (-0 and +0) keep m. y is one of the operands, bit for bit (NaN payloads included).
// One pipeline stage (comparator latency): the result for cycle c is on y in cycle c + 1.
module fp32_minmax (
    input  logic        clk,
    input  logic        en,
    input  logic [31:0] m,
    input  logic [31:0] x,
    input  logic        max,
    output logic [31:0] y
);
  import fp32_pkg::*;
  always_ff @(posedge clk) begin
    if (en) y <= max ? max_ignore_nan(m, x) : min_ignore_nan(m, x);
  end
endmodule
