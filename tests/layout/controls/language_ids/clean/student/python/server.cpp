// A server says which language it is.
const bool mine = language == "python";
