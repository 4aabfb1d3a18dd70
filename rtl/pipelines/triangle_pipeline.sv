// Fused ray-triangle pipeline: triangle_hit_test of firmware/common/intersect.h, bit for bit
// (hit bit and TrianglePartial: e0, e1, e2, t_num, t_den), issue width 2: two independent
// lanes, each accepting one test per initiation interval (II = 18 cycles) with a latency of
// 31 cycles (triangle_datapath_pkg::FAST_TAP). The divide (triangle_finish) stays a separate
// operation, as in the model. docs/rtl-cosim.md has the schedule and the stage diagram.
//
// Slow path: when an edge difference p - q is exactly zero, detail::edge_function takes its
// exact fallback (product_error); its chain of 11 dependent operations makes the result
// ready at EXACT_TAP = 33 instead of 31. Such a result is presented 2 cycles later (out_exact
// = 1). The lane's II is unchanged, and results stay in order (EXACT_TAP < FAST_TAP + II).
//
// Ports carry both lanes: bits [31:0] (or bit 0) are lane 0, [63:32] (bit 1) lane 1. Per
// lane: an operation is accepted in a cycle with in_valid && in_ready; its result is
// presented with out_valid and leaves in a cycle with out_valid && out_ready. A lane stalls
// entirely while its result waits (in_ready low), and in_ready is also low for II - 1 cycles
// after each acceptance. The partial is presented on a miss too (the ISA's strata.tritest
// keeps the previous partial on a miss: that latch is the issuer's, not this unit's).
// rst is synchronous, active high; it clears the valid bits and the II counters.
module triangle_pipeline (
    input  logic            clk,
    input  logic            rst,
    input  logic [1:0]      in_valid,
    output logic [1:0]      in_ready,
    input  logic [1:0][31:0] v0_x,
    input  logic [1:0][31:0] v0_y,
    input  logic [1:0][31:0] v0_z,
    input  logic [1:0][31:0] v1_x,
    input  logic [1:0][31:0] v1_y,
    input  logic [1:0][31:0] v1_z,
    input  logic [1:0][31:0] v2_x,
    input  logic [1:0][31:0] v2_y,
    input  logic [1:0][31:0] v2_z,
    input  logic [1:0][31:0] origin_x,
    input  logic [1:0][31:0] origin_y,
    input  logic [1:0][31:0] origin_z,
    input  logic [1:0][31:0] dir_x,
    input  logic [1:0][31:0] dir_y,
    input  logic [1:0][31:0] dir_z,
    output logic [1:0]      out_valid,
    input  logic [1:0]      out_ready,
    output logic [1:0]      out_hit,
    output logic [1:0]      out_exact,   // the result took the exact-fallback (slow) path
    output logic [1:0][31:0] out_e0,
    output logic [1:0][31:0] out_e1,
    output logic [1:0][31:0] out_e2,
    output logic [1:0][31:0] out_t_num,
    output logic [1:0][31:0] out_t_den
);
  for (genvar l = 0; l < 2; l++) begin : g_lane
    triangle_lane #(.II(18)) u_lane (
        .clk, .rst,
        .in_valid(in_valid[l]), .in_ready(in_ready[l]),
        .v0_x(v0_x[l]), .v0_y(v0_y[l]), .v0_z(v0_z[l]),
        .v1_x(v1_x[l]), .v1_y(v1_y[l]), .v1_z(v1_z[l]),
        .v2_x(v2_x[l]), .v2_y(v2_y[l]), .v2_z(v2_z[l]),
        .origin_x(origin_x[l]), .origin_y(origin_y[l]), .origin_z(origin_z[l]),
        .dir_x(dir_x[l]), .dir_y(dir_y[l]), .dir_z(dir_z[l]),
        .out_valid(out_valid[l]), .out_ready(out_ready[l]),
        .out_hit(out_hit[l]), .out_exact(out_exact[l]),
        .out_e0(out_e0[l]), .out_e1(out_e1[l]), .out_e2(out_e2[l]),
        .out_t_num(out_t_num[l]), .out_t_den(out_t_den[l]));
  end
endmodule
