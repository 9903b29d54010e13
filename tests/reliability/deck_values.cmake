# Deck files with bad values, duplicate keys and runs with nothing to do: exit code 2 and a
# message naming the key and file.
