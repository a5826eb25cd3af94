#include "pluginhost/XlibHostSetup.h"

#include <X11/Xlib.h>
#include <atomic>

namespace rosin::pluginhost
{

namespace
{
std::atomic<int> errors{0};

int countAndIgnore(Display*, XErrorEvent*)
{
    errors.fetch_add(1);
    return 0;
}
} // namespace

void prepareXlibAsADesktopHostDoes()
{
    XInitThreads();
    XSetErrorHandler(countAndIgnore);
}

int ignoredXErrors()
{
    return errors.load();
}

} // namespace rosin::pluginhost
