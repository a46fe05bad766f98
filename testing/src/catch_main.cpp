// The main() of every test executable. Catch2 v2 exits with the number of failed assertions (up
// to 255): a test case with exactly four failures would exit with 4, the code CTest reads as
// "skipped" (testing::skip, SKIP_RETURN_CODE 4), and pass unseen. A failure here is always 1.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
  const int failed = Catch::Session().run(argc, argv);
  return failed == 0 ? 0 : 1;
}
