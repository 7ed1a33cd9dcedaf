// The table's own room may name its ids.
bool is_python(const std::string& id) { return id == "python"; }
