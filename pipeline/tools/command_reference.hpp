// The command reference, generated from the declarations that parse the
// command line (the parameter table and each command's options), as
// FFmpeg's documentation comes from its option tables: as Markdown
// (docs/commands.md) and as a man page (docs/eyestream.1). A test checks
// that the committed files are what the program writes.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace eyestream::pipeline {

std::string markdown_reference(const CLI::App& app);
std::string man_page(const CLI::App& app);

}  // namespace eyestream::pipeline
