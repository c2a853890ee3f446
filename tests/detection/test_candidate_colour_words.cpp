// `--explain`'s words say what colour took from a plane: colour refuses only cells depth left
// free, so a few of them can move the picture (ufsec_livingroom_sofa_1: the dark top of the
// sofa's back cost the wall above it), and the reason must say so even when shadows cover more.
// And a tie is no "smaller rectangle".
#include <gtest/gtest.h>

#include <string>

#include "projsurf/detection/candidate_outcome.hpp"

using namespace projsurf;

namespace {

CandidateOutcome outcome(CandidateVerdict verdict, double shadowed, CellState colour, double colour_share) {
    CandidateOutcome o;
    o.verdict = verdict;
    o.rectangle.width = 0.24;
    o.rectangle.height = 0.15;
    o.beam_cells[static_cast<int>(CellState::InFront)] = shadowed;
    o.beam_cells[static_cast<int>(colour)] = colour_share;
    o.beam_cells[static_cast<int>(CellState::Free)] = 1.0 - shadowed - colour_share;
    return o;
}

bool says(const std::string &words, const std::string &part) { return words.find(part) != std::string::npos; }

Rectangle chosenRectangle() {
    Rectangle r;
    r.width = 0.5;
    r.height = 0.3;
    return r;
}

}  // namespace

TEST(CandidateColourWords, TheChosenPlaneSaysWhatColourTookBesideTheShadows) {
    const CandidateOutcome o = outcome(CandidateVerdict::Chosen, 0.57, CellState::Dark, 0.055);
    const std::string words = outcomeWords(o, o.rectangle);
    EXPECT_TRUE(says(words, "57 % of the beam's cells on it are shadowed")) << words;
    EXPECT_TRUE(says(words, "5.5 % of the beam's cells on it are too dark (low albedo)")) << words;
    // Under half a percent is not worth a clause.
    const std::string tiny = outcomeWords(outcome(CandidateVerdict::Chosen, 0.57, CellState::Dark, 0.004), o.rectangle);
    EXPECT_FALSE(says(tiny, "too dark")) << tiny;
}

TEST(CandidateColourWords, SmallerAndTooSmallPlanesSayItToo) {
    const std::string smaller =
        outcomeWords(outcome(CandidateVerdict::SmallerRectangle, 0.2, CellState::Textured, 0.03), chosenRectangle());
    EXPECT_TRUE(says(smaller, "a smaller rectangle")) << smaller;
    EXPECT_TRUE(says(smaller, "3.0 % of the beam's cells on it are unfit by their colour: textured")) << smaller;
    CandidateOutcome small = outcome(CandidateVerdict::TooSmall, 0.5, CellState::Glare, 0.04);
    small.detail = "too small: its rectangle, 0.144 x 0.090 m, is narrower than --min-width 0.150 m";
    const std::string words = outcomeWords(small, chosenRectangle());
    EXPECT_EQ(words.rfind(small.detail, 0), 0u) << words;
    EXPECT_TRUE(says(words, "4.0 % of the beam's cells on it are unfit by their colour: glare")) << words;
}

TEST(CandidateColourWords, ColourNamedAsTheBlockerIsNotSaidTwice) {
    const CandidateOutcome dark = outcome(CandidateVerdict::NoFreeArea, 0.1, CellState::Dark, 0.6);
    EXPECT_EQ(outcomeName(dark), "too_dark");
    const std::string words = outcomeWords(dark, Rectangle{});
    EXPECT_EQ(words, "no room for the picture: 60 % of the beam's cells on it are too dark (low albedo)");
    // Shadowed most, but colour took some of what was left: both said.
    const CandidateOutcome shadowed = outcome(CandidateVerdict::NoFreeArea, 0.6, CellState::Saturated, 0.1);
    EXPECT_EQ(outcomeName(shadowed), "shadowed");
    EXPECT_TRUE(says(outcomeWords(shadowed, Rectangle{}),
                     "10 % of the beam's cells on it are unfit by their colour: "
                     "too saturated"));
}

TEST(CandidateColourWords, ARectangleAsLargeAsTheChosenOneLostATieAndIsNotCalledSmaller) {
    const CandidateOutcome tie = outcome(CandidateVerdict::SmallerRectangle, 0.2, CellState::Dark, 0.0);
    const std::string words = outcomeWords(tie, tie.rectangle);
    EXPECT_EQ(words, "a rectangle as large as the chosen one, 0.240 x 0.150 m: a tie keeps the plane looked at first");
    Rectangle larger = tie.rectangle;
    larger.width = 0.25;
    EXPECT_TRUE(says(outcomeWords(tie, larger), "a smaller rectangle, 0.240 x 0.150 m")) << outcomeWords(tie, larger);
}
