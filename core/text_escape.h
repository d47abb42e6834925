#pragma once
/// \file text_escape.h
/// \brief Text from a user (sweep, campaign, series, geometry and run names, parameter values,
/// paths) written into another language: each function makes any string a literal of that
/// language, so that the text stays data. Nothing here validates; every input has an output.
///
/// The sinks and their rules:
/// - the terminal: control characters (C0, DEL, C1 as U+0080..U+009F), the bidirectional
///   overrides and isolates (U+202A..U+202E, U+2066..U+2069) and bytes that are not UTF-8 are
///   shown as \xHH or \u{HHHH}, a backslash as \\; so ESC, CR, NUL or a forged line cannot reach
///   the reader's terminal or log, and two different names never print alike;
/// - gnuplot: a single-quoted string, the one form in which gnuplot expands neither backquotes
///   (a shell command) nor @macros nor backslash escapes; its one escape is '' for ';
///   line breaks (which would end the command) are first made visible as for the terminal;
/// - CSV (RFC 4180): a field that holds a comma, a quote, a line break or leading or trailing
///   space is quoted, " doubled; the bytes themselves are kept (CSV is data: a reader gets the
///   name back as it was written);
/// - Markdown tables: | as \|, and one line per row (control characters as for the terminal);
/// - HTML: & < > " ' as entities.
#include <string>
#include <string_view>

namespace beverloo {

/// s with everything that a terminal could interpret shown as escapes (see above); printable
/// UTF-8 text is unchanged.
std::string terminal_safe(std::string_view s);

/// A gnuplot single-quoted string literal holding s (with its quotes).
std::string gnuplot_string(std::string_view s);

/// One RFC 4180 CSV field holding s (quoted where it must be).
std::string csv_field(std::string_view s);

/// A Markdown table cell holding s (no surrounding pipes).
std::string markdown_cell(std::string_view s);

/// s as HTML text or attribute value.
std::string html_escape(std::string_view s);

}  // namespace beverloo
