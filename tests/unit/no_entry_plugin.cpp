// A shared module without Strata's entry point, for plugin_loading_test.
extern "C" __attribute__((visibility("default"))) int not_a_strata_plugin() { return 42; }
