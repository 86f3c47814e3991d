#include <wash/wash.hpp>
int main() { return 0; }
