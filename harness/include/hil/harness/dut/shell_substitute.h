#pragma once
/// @file
/// The estimator's and the controller's command templates are trusted shell text (the user's
/// own command line); what hil pastes into them ({run_dir}, {path_file}, {ttyGPS}, {seed}, ...)
/// is data: a folder given with --out, a scenario's name, a path file's name, a sweep value.
/// Substitute quotes each value for the place it takes in the template, so that no value is ever
/// read as shell syntax (issue 40.4):
///   - outside quotes: single-quoted ('\'' for a quote inside), unless every character is plain
///     (letters, digits, `_@%+=:,./-`): the value then goes in as it is;
///   - inside '...': a single-quoted string in a command template is a script for another shell
///     (`sh -c '... {run_dir} ...'`); the value is quoted for that shell as above, then written
///     as text of the outer string ('\'' for each quote);
///   - inside "...": escaped (\ before `\`, `$`, `` ` `` and `"`), so it is text of the string.
///     A double-quoted string that is itself a script for another shell (`sh -c "..."`) would
///     read the value again: give such scripts in single quotes.

#include <string>
#include <utility>
#include <vector>

namespace hil::harness {

/// `value` as one shell word: itself when every character is plain, else single-quoted.
std::string ShellWord(const std::string& value);

/// Replaces every "{key}" of `text` whose key is in `vars` by its value quoted for its place in
/// the shell text (see above). One pass: a value holding "{key}" is not substituted again.
std::string Substitute(const std::string& text,
                       const std::vector<std::pair<std::string, std::string>>& vars);

}  // namespace hil::harness
