// A check that asks which language it runs: what a new row would have to be added to.
double factor(const SubjectInfo& info) { return info.language == "octave" ? 6 : 1; }
