# awk -v command='./step-2 block output-block' -f page_block.awk PAGE
# Prints the fenced code block of a results page that follows the first
# line naming COMMAND in backticks (`./step-2 block output-block`): the
# text a test compares, as a whole, with what the command prints.
index($0, "`" command "`") && !found { found = 1; next }
found && /^```/ { if (inside) exit; inside = 1; next }
inside { print }
