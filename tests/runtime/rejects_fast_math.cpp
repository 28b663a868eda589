// Must not compile with -ffast-math: finite-math-only would turn an immovable body (an infinite mass)
// into NaN silently, so the header refuses and says why.
#include <billiards/collision.hpp>

int main() { return 0; }
