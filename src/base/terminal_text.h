// Text from users (suite names, net names, keys, paths) on its way to a terminal: control characters escaped so a
// suite cannot move the cursor, clear the screen or retitle the window, and one line bounded so a megabyte key does
// not flood the log.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tcsb {

/// The longest error or warning line printed (bytes of the message, before the "tcsb: error: " prefix).
inline constexpr std::size_t kMaxMessageBytes = 500;

/// `text` safe to print: C0 controls and DEL as "\x1b", C1 controls (U+0080..U+009F, which some terminals obey like
/// ESC [) as "\u009b", and bytes that are not UTF-8 as "\xff"; printable UTF-8 is kept as is. With `max_bytes`, the
/// result is cut at a character boundary to at most that many bytes plus a suffix "… (N more bytes)" counting the
/// input bytes left out.
std::string terminal_safe(std::string_view text, std::size_t max_bytes = std::string_view::npos);

}  // namespace tcsb
