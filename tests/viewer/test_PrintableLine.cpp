// Messages built from bad input stay one line: a file name in a mutated scene held the
// text of the following lines (found by mutating scenes/examples, 3 in 1,400 inputs).
#include <gtest/gtest.h>

#include "viewer/PrintableLine.h"

using figment::viewer::printableLine;

TEST(PrintableLine, EscapesLineBreaksAndControlBytes) {
  EXPECT_EQ(printableLine("File { name \"incl\n  Switch {\n\" } not found"),
            "File { name \"incl\\n  Switch {\\n\" } not found");
  EXPECT_EQ(printableLine("a\rb\tc"), "a\\rb\\tc");
  EXPECT_EQ(printableLine(std::string("bell\x07 esc\x1b[31m del\x7f nul", 23) + '\0'),
            "bell\\x07 esc\\x1b[31m del\\x7f nul\\x00");
}

TEST(PrintableLine, KeepsPrintableTextAndUtf8) {
  EXPECT_EQ(printableLine("line 4: MeshFile 'Body': fileName \"nothere.obj\" not found"),
            "line 4: MeshFile 'Body': fileName \"nothere.obj\" not found");
  EXPECT_EQ(printableLine("Größe 2 µm"), "Größe 2 µm");
  EXPECT_EQ(printableLine(""), "");
}
