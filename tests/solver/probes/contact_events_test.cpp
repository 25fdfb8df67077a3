// The contact-event rule shared by every code's traces, on synthetic overlap histories.
#include <gtest/gtest.h>

#include "silodem/probes/contact_events.hpp"

using namespace silodem;

TEST(ContactEvents, InterpolatesOnsetAndOverlapEnd) {
  ContactEventDetector d(1.0, 0.0, false);
  d.sample(0.0, -0.2, 1.0);
  d.sample(1.0, 0.6, 1.0);   // crossed zero at t = 0.25
  d.sample(2.0, 0.4, -1.0);
  d.sample(3.0, -0.4, -2.0); // crossed zero at t = 2.5
  ASSERT_EQ(d.events().size(), 1u);
  const auto& e = d.events()[0];
  EXPECT_DOUBLE_EQ(e.t_start, 0.25);
  EXPECT_DOUBLE_EQ(e.t_end, 2.5);
  EXPECT_DOUBLE_EQ(e.restitution(), 2.0);
  EXPECT_DOUBLE_EQ(e.max_overlap, 0.6);
}

TEST(ContactEvents, ClampedContactEndsWhereTheForceVanishes) {
  // k = 1, c = 1: force δ + δ̇ goes from 0.5 − 0.2 = 0.3 to 0.2 − 0.5 = −0.3 → zero half-way.
  ContactEventDetector d(1.0, 1.0, true);
  d.sample(0.0, -0.1, 1.0);
  d.sample(1.0, 0.5, -0.2);
  d.sample(2.0, 0.2, -0.5);
  ASSERT_EQ(d.events().size(), 1u);
  EXPECT_TRUE(d.events()[0].ended);
  EXPECT_DOUBLE_EQ(d.events()[0].t_end, 1.5);
  EXPECT_DOUBLE_EQ(d.events()[0].rate_out, -0.5);
}

TEST(ContactEvents, TracksGapsAfterContact) {
  ContactEventDetector d(1.0, 0.0, false);
  d.sample(0.0, -0.5, 1.0);
  d.sample(1.0, 0.5, -1.0);
  d.sample(2.0, -0.3, -1.0);
  d.sample(3.0, -0.2, 1.0);
  EXPECT_DOUBLE_EQ(d.max_gap_after_contact(), 0.3);
  EXPECT_DOUBLE_EQ(d.max_gap(), 0.5);
}
