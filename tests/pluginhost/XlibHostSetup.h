#pragma once
// What a desktop host does with Xlib before it loads a plugin. JUCE does it itself only inside a
// JUCEApplication (pluginval is one; this test's main is not): without it the first ignorable X error ends
// the process through Xlib's default handler (under Xvfb, with no window manager, a BadAtom from a window
// manager property), and the plugin's own message thread and the host's share one unlocked connection
// library.

namespace rosin::pluginhost
{

/// Call first in main, before any other X call: XInitThreads, then an error handler that counts and ignores
/// errors (as JUCE's own handler in a standalone application does).
void prepareXlibAsADesktopHostDoes();

/// The X errors ignored so far.
int ignoredXErrors();

} // namespace rosin::pluginhost
