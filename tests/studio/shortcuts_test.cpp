// The one shortcut table: lookups as the window makes them; docs/studio.md's table must list
// exactly its rows, in its order, and the README's short table some of them, in the same order
// (so the docs cannot drift from the keys).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "gui/model/shortcuts.hpp"
#include "tests/test_paths.hpp"

namespace fs = fieldlines::studio;
using fs::Action;
using fs::Chord;
using fs::Key;

namespace {

using Row = std::pair<std::string, std::string>;  // input, description

std::vector<Row> table_rows() {
  std::vector<Row> rows;
  for (const fs::Shortcut& s : fs::shortcuts()) rows.emplace_back(fs::input_name(s), std::string(s.description));
  return rows;
}

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// The rows of the first "| Input | Action |" table after the line starting with `heading`, with
// the input's backticks removed.
std::vector<Row> markdown_rows(const std::filesystem::path& file, const std::string& heading) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  std::string line;
  while (std::getline(in, line) && line.rfind(heading, 0) != 0) {
  }
  while (std::getline(in, line) && line != "| Input | Action |") {
  }
  std::vector<Row> rows;
  while (std::getline(in, line) && line.rfind('|', 0) == 0) {
    if (line.rfind("|---", 0) == 0) continue;
    const auto mid = line.find(" | ");
    if (mid == std::string::npos || line.size() < 4) {
      ADD_FAILURE() << file << ": not a two-column row: " << line;
      continue;
    }
    std::string input = trim(line.substr(1, mid - 1));
    std::erase(input, '`');
    rows.emplace_back(input, trim(line.substr(mid + 3, line.size() - mid - 4)));
  }
  return rows;
}

}  // namespace

TEST(Shortcuts, TheStudioDocListsExactlyTheTable) {
  const std::vector<Row> expected = table_rows();
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(markdown_rows(fieldlines::test::source_dir() / "docs/studio.md", "## Labelling"), expected);
}

TEST(Shortcuts, TheReadmeListsRowsOfTheTableInItsOrder) {
  const std::vector<Row> table = table_rows();
  const std::vector<Row> readme = markdown_rows(fieldlines::test::source_dir() / "README.md", "## The studio");
  ASSERT_FALSE(readme.empty()) << "README.md: no \"| Input | Action |\" table under \"## The studio\"";
  auto next = table.begin();
  for (const Row& row : readme) {
    const auto found = std::find(next, table.end(), row);
    EXPECT_NE(found, table.end()) << "README.md row not in the table (or out of its order): " << row.first << " | "
                                  << row.second;
    if (found != table.end()) next = found + 1;
  }
}

TEST(Shortcuts, EveryKeyIsBoundOnceAndEveryActionHasAnInput) {
  std::set<std::pair<int, int>> chords;  // key, ctrl*2 + shift
  std::set<Action> actions;
  for (const fs::Shortcut& s : fs::shortcuts()) {
    actions.insert(s.action);
    EXPECT_FALSE(s.description.empty());
    if (s.chord.key == Key::None) {
      EXPECT_EQ(s.action, Action::Pointer);
      EXPECT_FALSE(s.pointer.empty());
      continue;
    }
    EXPECT_TRUE(chords.insert({static_cast<int>(s.chord.key), s.chord.ctrl * 2 + s.chord.shift}).second)
        << fs::input_name(s) << " is bound twice";
  }
  for (int a = 0; a <= static_cast<int>(Action::Pointer); ++a) EXPECT_TRUE(actions.count(static_cast<Action>(a))) << a;
}

TEST(Shortcuts, LookupAsTheWindowSeesKeys) {
  const auto action_of = [](Chord c, bool repeat = false) {
    const fs::Shortcut* s = fs::find_shortcut(c, repeat);
    return s ? std::optional<Action>(s->action) : std::nullopt;
  };
  EXPECT_EQ(action_of({Key::M}), Action::LabelMarking);
  EXPECT_EQ(action_of({Key::M, false, true}), Action::LabelMarking);  // Shift not named: ignored
  EXPECT_EQ(action_of({Key::M, true}), std::nullopt);                 // Ctrl+M is nothing
  EXPECT_EQ(action_of({Key::Z, true}), Action::Undo);
  EXPECT_EQ(action_of({Key::Z, true, true}), Action::Redo);
  EXPECT_EQ(action_of({Key::Y, true}), Action::Redo);
  EXPECT_EQ(action_of({Key::Z}), std::nullopt);
  EXPECT_EQ(action_of({Key::Right}, true), Action::NextImage);  // arrows repeat while held
  EXPECT_EQ(action_of({Key::M}, true), std::nullopt);           // a held M labels once
  EXPECT_EQ(action_of({Key::None}), std::nullopt);
  EXPECT_EQ(action_of({Key::Space}), Action::NextUnderCursor);  // overlapping segments
  EXPECT_EQ(action_of({Key::Space}, true), std::nullopt);        // one step per press
  EXPECT_EQ(fs::key_for(Action::NextUnderCursor), "Space");
  const fs::Shortcut* tab = fs::find_shortcut({Key::F4});
  ASSERT_NE(tab, nullptr);
  EXPECT_EQ(tab->action, Action::ShowTab);
  EXPECT_EQ(tab->tab, 3);
  EXPECT_EQ(fs::key_for(Action::Redo), "Ctrl+Shift+Z");
  EXPECT_EQ(fs::key_for(Action::NextImageWithErrors), "E");
  EXPECT_EQ(fs::key_for(Action::Pointer), "");
}

// The camera's nudges: arrows up and down tilt, Ctrl with the image arrows rolls (the plain
// arrows still change the image), Page Up / Down raise and lower; all repeat while held.
TEST(Shortcuts, CameraNudgesRepeatAndLeaveTheImageArrowsAlone) {
  const auto nudge_of = [](Chord c) {
    const fs::Shortcut* s = fs::find_shortcut(c, true);
    EXPECT_NE(s, nullptr) << static_cast<int>(c.key);
    return s && s->action == Action::NudgeCamera ? s->nudge : fs::CameraNudge{};
  };
  const auto same = [](fs::CameraNudge a, fs::CameraAxis axis, int direction) {
    return a.axis == axis && a.direction == direction;
  };
  EXPECT_TRUE(same(nudge_of({Key::Up}), fs::CameraAxis::Pitch, -1));
  EXPECT_TRUE(same(nudge_of({Key::Down}), fs::CameraAxis::Pitch, 1));
  EXPECT_TRUE(same(nudge_of({Key::Left, true}), fs::CameraAxis::Roll, -1));
  EXPECT_TRUE(same(nudge_of({Key::Right, true}), fs::CameraAxis::Roll, 1));
  EXPECT_TRUE(same(nudge_of({Key::PageUp}), fs::CameraAxis::Height, 1));
  EXPECT_TRUE(same(nudge_of({Key::PageDown}), fs::CameraAxis::Height, -1));
  EXPECT_EQ(fs::find_shortcut({Key::Left})->action, Action::PreviousImage);
  EXPECT_EQ(fs::input_name(*fs::find_shortcut({Key::PageUp})), "Page Up");
}

TEST(Shortcuts, EachFeatureLayerHasOneKeyAndTheLabellingKeysStay) {
  using fs::FeatureLayer;
  const std::pair<Key, FeatureLayer> expected[] = {{Key::G, FeatureLayer::FieldBoundary},
                                                   {Key::I, FeatureLayer::Intersections},
                                                   {Key::O, FeatureLayer::CentreCircle},
                                                   {Key::S, FeatureLayer::Stripes}};
  for (const auto& [key, layer] : expected) {
    const fs::Shortcut* s = fs::find_shortcut({key});
    ASSERT_NE(s, nullptr) << static_cast<char>(key);
    EXPECT_EQ(s->action, Action::ToggleFeatureLayer);
    EXPECT_EQ(s->layer, layer);
    EXPECT_EQ(fs::find_shortcut({key}, true), nullptr);  // held: toggles once
  }
  int toggles = 0;
  for (const fs::Shortcut& s : fs::shortcuts()) {
    if (s.action != Action::ToggleFeatureLayer) {
      EXPECT_EQ(s.layer, FeatureLayer::Count) << fs::input_name(s);
      continue;
    }
    ++toggles;
    EXPECT_NE(s.layer, FeatureLayer::Count);
  }
  EXPECT_EQ(toggles, 4);
  const std::pair<Chord, Action> labelling[] = {
      {{Key::M}, Action::LabelMarking},     {{Key::N}, Action::LabelNone},     {{Key::B}, Action::LabelBoundary},
      {{Key::P}, Action::Propose},          {{Key::Space}, Action::NextUnderCursor},
      {{Key::Enter}, Action::AcceptProposals}, {{Key::Tab}, Action::FocusUncertain}};
  for (const auto& [chord, action] : labelling) {
    const fs::Shortcut* s = fs::find_shortcut(chord);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->action, action);
  }
}
