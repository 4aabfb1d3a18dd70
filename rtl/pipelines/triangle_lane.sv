// One lane of the fused triangle pipeline (triangle_pipeline.sv has the contract).
// The datapath, its valid bits, the II counter and the output select.
module triangle_lane #(
    parameter int II = 18
) (
    input  logic        clk,
    input  logic        rst,
    input  logic        in_valid,
    output logic        in_ready,
    input  logic [31:0] v0_x, v0_y, v0_z,
    input  logic [31:0] v1_x, v1_y, v1_z,
    input  logic [31:0] v2_x, v2_y, v2_z,
    input  logic [31:0] origin_x, origin_y, origin_z,
    input  logic [31:0] dir_x, dir_y, dir_z,
    output logic        out_valid,
    input  logic        out_ready,
    output logic        out_hit,
    output logic        out_exact,
    output logic [31:0] out_e0, out_e1, out_e2, out_t_num, out_t_den
);
  import triangle_datapath_pkg::*;

  logic en, accept;
  logic [EXACT_TAP:1] valid;
  logic [7:0] since;  // enabled cycles since the last acceptance, saturating at II - 1
  logic fast_hit, fast_needs_exact, exact_hit, exact_needs_exact;
  logic [31:0] fast_e0, fast_e1, fast_e2, fast_t_num, fast_t_den;
  logic [31:0] exact_e0, exact_e1, exact_e2, exact_t_num, exact_t_den;
  logic fast_sel, exact_sel;

  assign en = !out_valid || out_ready;
  assign in_ready = en && (since == 8'(II - 1));
  assign accept = in_valid && in_ready;

  always_ff @(posedge clk) begin
    if (rst) begin
      valid <= '0;
      since <= 8'(II - 1);
    end else if (en) begin
      valid <= {valid[EXACT_TAP-1:1], accept};
      if (accept) since <= 8'd0;
      else if (since != 8'(II - 1)) since <= since + 8'd1;
    end
  end

  triangle_datapath u_datapath (.*);

  // A fast result leaves at FAST_TAP unless it needs the fallback; then the exact result
  // leaves at EXACT_TAP. Both at once is impossible: operations are at least II stages apart.
  assign fast_sel = valid[FAST_TAP] && !fast_needs_exact;
  assign exact_sel = valid[EXACT_TAP] && exact_needs_exact;
  assign out_valid = fast_sel || exact_sel;
  assign out_exact = exact_sel;
  assign out_hit = exact_sel ? exact_hit : fast_hit;
  assign out_e0 = exact_sel ? exact_e0 : fast_e0;
  assign out_e1 = exact_sel ? exact_e1 : fast_e1;
  assign out_e2 = exact_sel ? exact_e2 : fast_e2;
  assign out_t_num = exact_sel ? exact_t_num : fast_t_num;
  assign out_t_den = exact_sel ? exact_t_den : fast_t_den;
endmodule
