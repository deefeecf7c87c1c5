// Tests of the notes on scenes that parse but may not render what was meant (host/scene/scene_notes.cpp).
#include "parser.h"
#include "scene_notes.h"

#include <gtest/gtest.h>

#include <string>

namespace {

const std::string kMaterials =
    "material plain { diffuse = (0.5, 0.5, 0.5); }\n"
    "material stone { texture = marble { } }\n"
    "material tiles { texture = checker { } }\n";

std::vector<std::string> notesOf(const std::string& text) { return sceneNotes(parseSceneText(text, "n.cfg")); }

}  // namespace

TEST(SceneNotes, ObjectInTheDefaultMaterialBesideTexturedOnesGetsOneNoteAtTheObject) {
  const auto notes = notesOf(kMaterials + "sphere { stone; }\n  plane { }\n");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0],
            "n.cfg:5:3: note: this plane names no material, so it is plain grey (the default material); the scene "
            "defines textured materials (stone, tiles): to use one, name it inside the object's block, e.g. 'stone;'");
}

TEST(SceneNotes, SeveralObjectsInTheDefaultMaterialShareOneNoteAtTheFirst) {
  const auto notes = notesOf(kMaterials + "sphere { }\nsphere { }\nplane { }\n");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("n.cfg:4:1: note: this sphere (and 2 more objects) names no material", 0), 0u) << notes[0];
}

TEST(SceneNotes, ListsFourTexturedMaterialsThenEllipsis) {
  std::string text;
  for (const char* name : {"a", "b", "c", "d", "e"}) text += "material " + std::string(name) + " { texture = noise { } }\n";
  const auto notes = notesOf(text + "sphere { }\n");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("(a, b, c, d, ...)"), std::string::npos) << notes[0];
}

TEST(SceneNotes, NoNoteWhenEveryObjectNamesAMaterialOrNoneIsTextured) {
  EXPECT_TRUE(notesOf(kMaterials + "sphere { stone; }\nplane { plain; }\n").empty());
  EXPECT_TRUE(notesOf("material plain { }\nsphere { }\nplane { plain; }\n").empty());
  EXPECT_TRUE(notesOf("sphere { }\n").empty());
}
