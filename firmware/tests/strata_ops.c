/* The STRaTA extension through its intrinsics, against the ISS's functional hook (one TP,
 * one TM): ids, global registers, stream memory and both fused pipelines. */
#include "strata_runtime.h"
#include "firmware/abi/strata_isa.h"

static strata_stream_ray make_ray(uint32_t tag) {
  strata_stream_ray r;
  for (uint32_t i = 0; i < STRATA_STREAM_RAY_WORDS; ++i) r.words[i] = tag * 100u + i;
  return r;
}

static int ray_is(const strata_stream_ray* r, uint32_t tag) {
  for (uint32_t i = 0; i < STRATA_STREAM_RAY_WORDS; ++i)
    if (r->words[i] != tag * 100u + i) return 0;
  return 1;
}

int main(void) {
  STRATA_CHECK(strata_thread_id() == 0);
  STRATA_CHECK(strata_tp_id() == 0);
  STRATA_CHECK(strata_tm_id() == 0);
  STRATA_CHECK(strata_thread_count() == 1);
  STRATA_CHECK(strata_tps_per_tm() == 1);
  STRATA_CHECK(strata_tm_count() == 1);

  STRATA_CHECK(strata_atomic_inc(3) == 0);
  STRATA_CHECK(strata_atomic_inc(3) == 1);
  STRATA_CHECK(strata_atomic_add(3, 10) == 2);
  STRATA_CHECK(strata_global_read(3) == 12);
  strata_global_write(3, 0xABCDu);
  STRATA_CHECK(strata_global_read(3) == 0xABCDu);
  STRATA_CHECK(strata_global_read(4) == 0);

  /* Stream memory: LIFO per treelet; the assignment keeps a non-empty buffer. */
  STRATA_CHECK(strata_stream_capacity() > 0);
  STRATA_CHECK(strata_stream_assign() == STRATA_NO_TREELET);
  strata_stream_ray ray;
  for (uint32_t tag = 1; tag <= 3; ++tag) {
    ray = make_ray(tag);
    STRATA_CHECK(strata_stream_push(&ray, 5) == 1);
  }
  ray = make_ray(8);
  STRATA_CHECK(strata_stream_push(&ray, 7) == 1);
  STRATA_CHECK(strata_stream_assign() == 5);
  STRATA_CHECK(strata_stream_pop(&ray) == 1 && ray_is(&ray, 3));
  STRATA_CHECK(strata_stream_assign() == 5);
  STRATA_CHECK(strata_stream_pop(&ray) == 1 && ray_is(&ray, 2));
  STRATA_CHECK(strata_stream_pop(&ray) == 1 && ray_is(&ray, 1));
  STRATA_CHECK(strata_stream_pop(&ray) == 0);
  STRATA_CHECK(strata_stream_assign() == 7);
  STRATA_CHECK(strata_stream_pop(&ray) == 1 && ray_is(&ray, 8));
  STRATA_CHECK(strata_stream_assign() == STRATA_NO_TREELET);

  /* Box pipeline: a ray along +z from z = -1 through the unit cube. */
  const float inf = __builtin_inff();
  strata_pipe_ray pr = {{0.5f, 0.5f, -1.0f}, 0.0f, {0.0f, 0.0f, 1.0f}, inf, {inf, inf, 1.0f}, 0.0f};
  const strata_pipe_box hit_box = {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};
  const strata_pipe_box miss_box = {{2.0f, 0.0f, 0.0f}, {3.0f, 1.0f, 1.0f}};
  float t;
  strata_pipe_box_mode();
  strata_load_ray(&pr);
  strata_load_box(&hit_box);
  STRATA_CHECK(strata_box_test(&t) == 1 && t == 1.0f);
  strata_load_box(&miss_box);
  STRATA_CHECK(strata_box_test(&t) == 0 && t == inf);
  strata_set_tmax(0.5f); /* the box starts at t = 1, beyond tmax */
  strata_load_box(&hit_box);
  STRATA_CHECK(strata_box_test(&t) == 0);

  /* Triangle pipeline: the hit is decided first, the division runs separately. */
  const strata_pipe_triangle tri = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
  strata_pipe_ray pr2 = {{0.25f, 0.25f, -1.0f}, 0.0f, {0.0f, 0.0f, 1.0f}, inf, {inf, inf, 1.0f}, 0.0f};
  strata_pipe_triangle_mode();
  strata_load_ray(&pr2);
  strata_load_triangle(&tri);
  STRATA_CHECK(strata_triangle_test() == 1);
  float u, v;
  strata_triangle_divide(&t, &u, &v);
  STRATA_CHECK(t == 1.0f && u == 0.25f && v == 0.25f);
  /* The division-free test ignores tmax; firmware compares the divided t, as traverse.h does. */
  strata_set_tmax(0.5f);
  STRATA_CHECK(strata_triangle_test() == 1);
  strata_triangle_divide(&t, &u, &v);
  STRATA_CHECK(!(t < 0.5f));
  pr2.origin[0] = 0.75f; /* outside the hypotenuse */
  pr2.origin[1] = 0.75f;
  strata_load_ray(&pr2);
  STRATA_CHECK(strata_triangle_test() == 0);
  strata_pipe_general();
  return 0;
}
