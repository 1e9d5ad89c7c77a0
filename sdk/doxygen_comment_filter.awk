# Doxygen's INPUT_FILTER for the SDK headers (sdk/CMakeLists.txt, target sdk-reference): hands Doxygen their
# plain // comments as its own, so that the headers keep the project's comment style. A comment on lines of
# its own documents what follows it (///); one after a declaration on its line documents that declaration
# (///<), and so do the comment lines below it that start in the same column. In the comments' text, < > and
# # are escaped: the headers write <prefix>/lib and #version as plain text, not HTML or links.
function column_of(text, pattern) { return match(text, pattern) ? RSTART : 0 }

# `line` with the text after its first // escaped for Doxygen.
function escape_comment(line,    at, text) {
  at = index(line, "//")
  if (at == 0) return line
  text = substr(line, at + 2)
  gsub(/</, "\\<", text)
  gsub(/>/, "\\>", text)
  gsub(/#/, "\\#", text)
  return substr(line, 1, at + 1) text
}

{
  line = escape_comment($0)
  if (line ~ /^[ \t]*\/\//) {
    if (trailing && column_of(line, /\/\//) == trailing) sub(/\/\//, "///<", line)
    else { sub(/\/\//, "///", line); trailing = 0 }
  } else if (line !~ /^[ \t]*[}#]/ && line !~ /"[^"]*\/\/[^"]*"/ && match(line, /[^ \t][ \t]+\/\/ /)) {
    trailing = column_of(line, / \/\/ /) + 1
    sub(/ \/\/ /, " ///< ", line)
  } else {
    trailing = 0
  }
  print line
}
