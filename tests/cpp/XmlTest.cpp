// Names as users typed them, made safe for every file.
#include "IO/Xml.h"

#include <gtest/gtest.h>

using fabguide::io::escapeXml;
using fabguide::io::plainText;

TEST(Xml, PlainTextKeepsEveryCharacterAndReplacesControlsAndBrokenUtf8)
{
    EXPECT_EQ(plainText("Tür – 棚 🪚"), "Tür – 棚 🪚");
    const std::string replacement = "\xEF\xBF\xBD";
    EXPECT_EQ(plainText("a\nb\tc"), "a" + replacement + "b" + replacement + "c");
    EXPECT_EQ(plainText(std::string("nul\0!", 5)), "nul" + replacement + "!");
    EXPECT_EQ(plainText("\x7F"), replacement);
    EXPECT_EQ(plainText("\xC3"), replacement);                                      // cut short
    EXPECT_EQ(plainText("\xC0\xAF"), replacement + replacement);                    // overlong '/'
    EXPECT_EQ(plainText("\xED\xA0\x80"), replacement + replacement + replacement);  // a surrogate
    EXPECT_EQ(escapeXml("a & <b> \"c\"\x01"), "a &amp; &lt;b&gt; &quot;c&quot;" + replacement);
}
