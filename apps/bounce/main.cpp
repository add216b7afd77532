// bounce: collision physics of adhesive, viscoelastic grains (command line).
#include "cli.hpp"

int main(int argc, char** argv) {
  bounce::cli::exit_on_interrupt();
  return bounce::cli::run(argc, argv);
}
