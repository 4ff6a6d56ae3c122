// gpsurf: the command line. Each subcommand lives in its own cmd_*.cpp; errors are caught once here.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

#include "core/error.h"

int main(int argc, char** argv) {
  CLI::App app{"gpsurf: Gaussian-product subdivision surfaces"};
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const gps::Error& e) {
    std::cerr << "gpsurf: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "gpsurf: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
