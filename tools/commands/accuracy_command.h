#pragma once
/// @file accuracy_command.h
/// `foresight accuracy`: measures how far the reference article's methods are from the exact
/// ones (and the exact ones from closed forms) on fixed cases, and prints the tables that the
/// README quotes. Everything is computed on the spot; nothing is stored.

namespace foresight_cli {

/// Prints the accuracy tables (Markdown) to standard output. Returns the exit status.
int accuracyCommand();

}  // namespace foresight_cli
