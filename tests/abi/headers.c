/* Compiled as C89 and as C++ by CTest: the public headers must stay usable from both. */
#include <bezsurf.h>

int bs_headers_compile(void);
int bs_headers_compile(void)
{
    bs_view view;
    view.data = 0;
    view.count = 0;
    view.stride = 0;
    return (int)view.count + BS_OK + BS_VERSION_MAJOR;
}
