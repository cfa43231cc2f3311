#include "pfdm/fit/stages/temporal_prior.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

ModelState StateOf(double value, int knots) {
  ModelState state;
  state.globals.fill(value);
  state.knots.assign(knots, FunctionValues{});
  for (auto& knot : state.knots) knot.fill(value);
  return state;
}

// Frame 0's pull (0.01) and the previous frame's (0.03) are one pull of
// 0.04 toward the point a quarter of the way from the previous state to
// frame 0's.
TEST(TemporalPriorTest, UntrackedFramesMixFrameZeroAndThePreviousFrame) {
  FitOptions options;
  options.untracked_prior_weight = 0.01;
  options.temporal_prior_weight = 0.03;
  const FramePrior prior = PriorOfFrame(FrameKind::kUntracked, StateOf(2.0, 3),
                                        StateOf(6.0, 3), false, options);
  EXPECT_DOUBLE_EQ(prior.options.untracked_prior_weight, 0.04);
  for (double g : prior.state.globals) EXPECT_DOUBLE_EQ(g, 5.0);
  ASSERT_EQ(prior.state.knots.size(), 3u);
  for (const auto& knot : prior.state.knots) {
    for (double f : knot) EXPECT_DOUBLE_EQ(f, 5.0);
  }
}

// The sum of the two quadratics is the mixed one's plus a constant: the
// gradients agree everywhere (checked at a few values of one function).
TEST(TemporalPriorTest, OneMixedPullEqualsTheTwoPulls) {
  const double w0 = 0.01, w1 = 0.05, a = 1.3, b = -0.4;
  FitOptions options;
  options.untracked_prior_weight = w0;
  options.temporal_prior_weight = w1;
  const FramePrior prior = PriorOfFrame(FrameKind::kUntracked, StateOf(a, 2),
                                        StateOf(b, 2), false, options);
  const double m = prior.state.knots[0][0];
  const double w = prior.options.untracked_prior_weight;
  for (double x : {-2.0, 0.0, 0.7, 5.0}) {
    const double two = w0 * (x - a) * (x - a) + w1 * (x - b) * (x - b);
    const double one = w * (x - m) * (x - m);
    const double constant = w0 * (m - a) * (m - a) + w1 * (m - b) * (m - b);
    EXPECT_NEAR(two, one + constant, 1e-12) << x;
  }
}

TEST(TemporalPriorTest, OtherFramesAndNoWeightKeepTheirPriors) {
  FitOptions options;
  options.temporal_prior_weight = 0.05;
  const ModelState reference = StateOf(1.0, 2), previous = StateOf(3.0, 2);
  for (FrameKind kind : {FrameKind::kReference, FrameKind::kTracked}) {
    const FramePrior prior =
        PriorOfFrame(kind, reference, previous, false, options);
    EXPECT_DOUBLE_EQ(prior.state.knots[1][0], 3.0);
    EXPECT_DOUBLE_EQ(prior.options.untracked_prior_weight,
                     options.untracked_prior_weight);
  }
  // The frame after frame 0: its previous frame is frame 0.
  const FramePrior second =
      PriorOfFrame(FrameKind::kUntracked, reference, reference, true, options);
  EXPECT_DOUBLE_EQ(second.state.knots[1][0], 1.0);
  EXPECT_DOUBLE_EQ(second.options.untracked_prior_weight,
                   options.untracked_prior_weight);
  options.temporal_prior_weight = 0.0;  // Off.
  const FramePrior none =
      PriorOfFrame(FrameKind::kUntracked, reference, previous, false, options);
  EXPECT_DOUBLE_EQ(none.state.knots[1][0], 1.0);
  EXPECT_DOUBLE_EQ(none.options.untracked_prior_weight,
                   options.untracked_prior_weight);
}

// A round's pull toward its start adds to the weight of the frame's kind:
// an untracked frame's prior (0.01) and a pull of 1 toward 12 are one pull
// of 1.01 toward 12 - 10 / 101; the reference's (prior_weight, 0.001)
// likewise, the other weight untouched.
TEST(TemporalPriorTest, ARoundsPullTowardItsStartJoinsTheFramesPrior) {
  FitOptions options;
  options.untracked_prior_weight = 0.01;
  options.prior_weight = 0.001;
  const ModelState prior = StateOf(2.0, 3), start = StateOf(12.0, 3);
  const FramePrior untracked =
      PulledTowardStart(FrameKind::kUntracked, prior, options, start, 1.0);
  EXPECT_DOUBLE_EQ(untracked.options.untracked_prior_weight, 1.01);
  EXPECT_DOUBLE_EQ(untracked.options.prior_weight, 0.001);
  EXPECT_DOUBLE_EQ(untracked.state.knots[2][kH], 12.0 - 10.0 / 101.0);
  EXPECT_DOUBLE_EQ(untracked.state.globals[kA0], 12.0 - 10.0 / 101.0);
  const FramePrior reference =
      PulledTowardStart(FrameKind::kReference, prior, options, start, 1.0);
  EXPECT_DOUBLE_EQ(reference.options.prior_weight, 1.001);
  EXPECT_DOUBLE_EQ(reference.options.untracked_prior_weight, 0.01);
  EXPECT_DOUBLE_EQ(reference.state.knots[0][kA1], 12.0 - 10.0 / 1001.0);
  // Without a prior of its own, the pull's target is the start.
  options.prior_weight = 0.0;
  const FramePrior alone =
      PulledTowardStart(FrameKind::kTracked, prior, options, start, 1.0);
  EXPECT_DOUBLE_EQ(alone.options.prior_weight, 1.0);
  EXPECT_DOUBLE_EQ(alone.state.knots[1][kTau], 12.0);
}

// By default, sequences of a cine's length; shorter ones not at all.
TEST(TemporalPriorTest, CineLengthSequencesArePulledByDefault) {
  const FitOptions options;
  EXPECT_DOUBLE_EQ(options.temporal_prior_weight,
                   kSuggestedTemporalPriorWeight);
  EXPECT_DOUBLE_EQ(TemporalPriorWeightFor(25, options), 0.05);
  EXPECT_DOUBLE_EQ(TemporalPriorWeightFor(20, options), 0.05);
  EXPECT_DOUBLE_EQ(TemporalPriorWeightFor(19, options), 0.0);
  EXPECT_DOUBLE_EQ(TemporalPriorWeightFor(9, options), 0.0);
}

}  // namespace
}  // namespace pfdm
