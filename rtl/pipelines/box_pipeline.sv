// Fused ray-box pipeline: intersect_box of firmware/common/intersect.h, one box per operation
// (strata.boxtest tests one box; the traversal issues one per child), bit for bit.
// docs/rtl-cosim.md has the stage diagram.
//
// Per axis, in the order x, y, z:
//   positive  = !(inv < 0)                         (+0, +inf and NaN count as positive)
//   near, far = positive ? (bmin, bmax) : (bmax, bmin)
//   t0 = (near - o) * inv,  t1 = ((far - o) * inv) * kFarPad
// t_near = max_ignore_nan chain from tmin over t0x, t0y, t0z; t_far = min_ignore_nan chain
// from tmax over t1x, t1y, t1z; overlap = t_near <= t_far (intersect_box_valid_ray);
// hit = overlap && box_ray_is_valid (intersect_box); t_entry = t_near.
//
// Stages (LATENCY = 8 cycles, initiation interval 1):
//   1-2  6 subtracts (fp32_add)          near - o, far - o per axis; plane select by sign(inv)
//   3-4  6 multiplies (fp32_mul)         t0 = (near - o) * inv, (far - o) * inv
//   5-6  3 multiplies by kFarPad         t1; t0 waits in registers
//   7    running max / min (comparators) both chains in one compare level: all 6 ordered
//                                        comparisons per chain in parallel, then a select
//   8    t_near <= t_far (comparator)    overlap, hit
// The multiply by the constant kFarPad = 1 + 2^-21 is a separate multiplier stage that the
// architecture's count of 6 multipliers and 6 adders does not include (docs/rtl-cosim.md).
//
// Handshake: an operation is accepted in a cycle with in_valid && in_ready; its result is
// presented LATENCY cycles later with out_valid, and leaves in a cycle with out_valid &&
// out_ready. The whole pipeline stalls while a result waits (out_valid && !out_ready), so
// in_ready = !out_valid || out_ready. rst is synchronous, active high, and clears the
// valid bits only.
module box_pipeline (
    input  logic        clk,
    input  logic        rst,
    // operation in
    input  logic        in_valid,
    output logic        in_ready,
    input  logic [31:0] bmin_x,
    input  logic [31:0] bmin_y,
    input  logic [31:0] bmin_z,
    input  logic [31:0] bmax_x,
    input  logic [31:0] bmax_y,
    input  logic [31:0] bmax_z,
    input  logic [31:0] origin_x,
    input  logic [31:0] origin_y,
    input  logic [31:0] origin_z,
    input  logic [31:0] inv_dir_x,
    input  logic [31:0] inv_dir_y,
    input  logic [31:0] inv_dir_z,
    input  logic [31:0] tmin,
    input  logic [31:0] tmax,
    // result out
    output logic        out_valid,
    input  logic        out_ready,
    output logic        out_hit,      // intersect_box
    output logic        out_overlap,  // intersect_box_valid_ray (hit without the ray check)
    output logic [31:0] out_t_entry   // t_near, on a hit or a miss
);
  import fp32_pkg::*;

  localparam int LATENCY = 8;
  localparam logic [31:0] FAR_PAD = 32'h3F80_0008;  // 1 + 2^-21

  logic en;
  logic [LATENCY:1] valid;  // valid[k]: stage k holds an operation
  assign en = !valid[LATENCY] || out_ready;
  assign in_ready = en;
  assign out_valid = valid[LATENCY];

  always_ff @(posedge clk) begin
    if (rst) valid <= '0;
    else if (en) valid <= {valid[LATENCY-1:1], in_valid};
  end

  logic [31:0] bmin[3], bmax[3], o[3], inv[3];
  assign bmin = '{bmin_x, bmin_y, bmin_z};
  assign bmax = '{bmax_x, bmax_y, bmax_z};
  assign o = '{origin_x, origin_y, origin_z};
  assign inv = '{inv_dir_x, inv_dir_y, inv_dir_z};

  // box_ray_is_valid: finite origin, no NaN and no zero inverse-direction component.
  logic ray_ok;
  always_comb begin
    ray_ok = 1'b1;
    for (int i = 0; i < 3; i++) begin
      if (!is_finite(o[i]) || is_nan(inv[i]) || is_zero(inv[i])) ray_ok = 1'b0;
    end
  end

  // Values that ride along: inv for stages 3-4, tmin/tmax and ray_ok up to stage 7/8.
  logic [31:0] inv_q[1:2][3];
  logic [31:0] tmin_q[1:6], tmax_q[1:6];
  logic ray_ok_q[1:7];
  always_ff @(posedge clk) begin
    if (en) begin
      inv_q[1] <= inv;
      inv_q[2] <= inv_q[1];
      tmin_q[1] <= tmin;
      tmax_q[1] <= tmax;
      ray_ok_q[1] <= ray_ok;
      for (int k = 2; k <= 6; k++) begin
        tmin_q[k] <= tmin_q[k-1];
        tmax_q[k] <= tmax_q[k-1];
      end
      for (int k = 2; k <= 7; k++) ray_ok_q[k] <= ray_ok_q[k-1];
    end
  end

  // Stages 1-6: per axis, two subtracts, two multiplies, the pad multiply.
  logic [31:0] d_near[3], d_far[3], t0_raw[3], t1_raw[3], t1[3];
  logic [31:0] t0_q5[3], t0_q6[3];
  for (genvar i = 0; i < 3; i++) begin : g_axis
    logic positive;
    assign positive = !lt(inv[i], 32'h0000_0000);
    fp32_add u_sub_near (.clk, .en, .a(positive ? bmin[i] : bmax[i]), .b(o[i]), .sub(1'b1), .y(d_near[i]));
    fp32_add u_sub_far (.clk, .en, .a(positive ? bmax[i] : bmin[i]), .b(o[i]), .sub(1'b1), .y(d_far[i]));
    fp32_mul u_mul_near (.clk, .en, .a(d_near[i]), .b(inv_q[2][i]), .y(t0_raw[i]));
    fp32_mul u_mul_far (.clk, .en, .a(d_far[i]), .b(inv_q[2][i]), .y(t1_raw[i]));
    fp32_mul u_mul_pad (.clk, .en, .a(t1_raw[i]), .b(FAR_PAD), .y(t1[i]));
    always_ff @(posedge clk) begin
      if (en) begin
        t0_q5[i] <= t0_raw[i];
        t0_q6[i] <= t0_q5[i];
      end
    end
  end

  // Stage 7: the running max and min of intersect.h in one compare level. For the chain
  // r0 = first, r_k = lt(r_{k-1}, x_k) ? x_k : r_{k-1} (max; min swaps the comparison),
  // every comparison a later step needs is one of the six pairwise ones below, all computed
  // at once; the select logic then follows the chain exactly (NaNs and signed zeros included).
  function automatic logic [31:0] chain3(input logic [31:0] r0, input logic [31:0] x1,
                                         input logic [31:0] x2, input logic [31:0] x3,
                                         input logic is_max);
    logic c01, c02, c03, c12, c13, c23;  // cij: x_j replaces x_i (x_0 = r0)
    logic s1, s2, s3;
    logic [31:0] r1, r2;
    c01 = is_max ? lt(r0, x1) : lt(x1, r0);
    c02 = is_max ? lt(r0, x2) : lt(x2, r0);
    c03 = is_max ? lt(r0, x3) : lt(x3, r0);
    c12 = is_max ? lt(x1, x2) : lt(x2, x1);
    c13 = is_max ? lt(x1, x3) : lt(x3, x1);
    c23 = is_max ? lt(x2, x3) : lt(x3, x2);
    s1 = c01;
    r1 = s1 ? x1 : r0;
    s2 = s1 ? c12 : c02;
    r2 = s2 ? x2 : r1;
    s3 = s2 ? c23 : (s1 ? c13 : c03);
    return s3 ? x3 : r2;
  endfunction

  logic [31:0] t_near_q, t_far_q;
  always_ff @(posedge clk) begin
    if (en) begin
      t_near_q <= chain3(tmin_q[6], t0_q6[0], t0_q6[1], t0_q6[2], 1'b1);
      t_far_q <= chain3(tmax_q[6], t1[0], t1[1], t1[2], 1'b0);
    end
  end

  // Stage 8: t_near <= t_far.
  always_ff @(posedge clk) begin
    if (en) begin
      out_overlap <= le(t_near_q, t_far_q);
      out_hit <= le(t_near_q, t_far_q) && ray_ok_q[7];
      out_t_entry <= t_near_q;
    end
  end
endmodule
