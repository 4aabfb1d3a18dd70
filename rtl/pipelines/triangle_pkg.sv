// Helpers of the triangle pipeline's frame selection (intersect.h: triangle_hit_test step 1
// and detail::direction_scale): pure bit and compare logic, no arithmetic unit.
package triangle_pkg;
  import fp32_pkg::*;

  // detail::abs_f(x) = x < 0 ? -x : x (so -0 and NaNs keep their sign bit).
  function automatic logic [31:0] abs_f(input logic [31:0] x);
    return lt(x, 32'h0000_0000) ? {~x[31], x[30:0]} : x;
  endfunction

  // kz: the axis of the largest |dir| component, ties z, then y, then x.
  function automatic logic [1:0] kz_of(input logic [31:0] adx, input logic [31:0] ady,
                                       input logic [31:0] adz);
    logic [1:0] k;
    if (le(adx, adz) && le(ady, adz)) k = 2'd2;
    else k = le(adx, ady) ? 2'd1 : 2'd0;
    return k;
  endfunction

  // kx and ky follow kz cyclically, swapped when dir[kz] < 0.
  function automatic logic [1:0] next_axis(input logic [1:0] k);
    return (k == 2'd2) ? 2'd0 : k + 2'd1;
  endfunction

  function automatic logic [1:0] kx_of(input logic [1:0] kz, input logic neg);
    return neg ? next_axis(next_axis(kz)) : next_axis(kz);
  endfunction

  function automatic logic [1:0] ky_of(input logic [1:0] kz, input logic neg);
    return neg ? next_axis(kz) : next_axis(next_axis(kz));
  endfunction

  function automatic logic [31:0] sel3(input logic [31:0] x, input logic [31:0] y,
                                       input logic [31:0] z, input logic [1:0] k);
    return (k == 2'd0) ? x : ((k == 2'd1) ? y : z);
  endfunction

  // direction_scale: the biased exponent E of m clamped to [1, 253]; scale = 2^(127-E),
  // unscale = 2^(E-127), built from the exponent bits.
  /* verilator lint_off UNUSEDSIGNAL */  // only the exponent field is read
  function automatic logic [7:0] clamped_exponent(input logic [31:0] m);
    logic [7:0] e;
    e = m[30:23];
    if (e < 8'd1) e = 8'd1;
    if (e > 8'd253) e = 8'd253;
    return e;
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */

  function automatic logic [31:0] scale_of(input logic [31:0] m);
    return {1'b0, 8'd254 - clamped_exponent(m), 23'd0};
  endfunction

  function automatic logic [31:0] unscale_of(input logic [31:0] m);
    return {1'b0, clamped_exponent(m), 23'd0};
  endfunction

  // The hit rule after the edge terms (triangle_hit_test): terms of one sign, det finite with
  // |det| >= 2^-126, t_num and t_den finite, |t_den| >= 2^-126, t_num and t_den of one sign,
  // and the exact t positive too (detail::t_exactly_positive): every vertex ahead beyond its
  // depth's rounding error (all_ahead), or the origin's orientation against the plane of
  // t_den's sign beyond its bound. The sign flip of -bound is exact, as in the C++.
  localparam logic [31:0] MIN_NORMAL = 32'h0080_0000;
  localparam logic [31:0] ZERO = 32'h0000_0000;
  function automatic logic hit_rule(input logic [31:0] e0, input logic [31:0] e1,
                                    input logic [31:0] e2, input logic [31:0] det,
                                    input logic [31:0] t_num, input logic [31:0] t_den,
                                    input logic all_ahead, input logic [31:0] orient,
                                    input logic [31:0] orient_bound);
    logic all_nonneg, all_nonpos, det_ok, t_ok, in_front, exactly_ahead;
    all_nonneg = le(ZERO, e0) && le(ZERO, e1) && le(ZERO, e2);
    all_nonpos = le(e0, ZERO) && le(e1, ZERO) && le(e2, ZERO);
    det_ok = le(MIN_NORMAL, abs_f(det)) && is_finite(det);
    t_ok = is_finite(t_num) && is_finite(t_den) && le(MIN_NORMAL, abs_f(t_den));
    in_front = lt(ZERO, t_den) ? lt(ZERO, t_num) : lt(t_num, ZERO);
    exactly_ahead = all_ahead || (lt(ZERO, t_den) ? lt(orient_bound, orient)
                                                  : lt(orient, {~orient_bound[31], orient_bound[30:0]}));
    return (all_nonneg || all_nonpos) && det_ok && t_ok && in_front && exactly_ahead;
  endfunction
endpackage
