// A shared library that is not a facet plugin: it exports a function, but not the entry symbol.

extern "C" __attribute__((visibility("default"))) int facet_test_not_a_plugin() {
  return 42;
}
