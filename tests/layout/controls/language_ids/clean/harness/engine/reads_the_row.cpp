// A room that reads the row: nothing here asks which language it is (a comment may say == "python").
double timeout_factor(const Language& l) { return l.timeout_factor; }
const char* noun = "a \"python\" // not a comparison";
