enum class ShowStyle { Cpp, Python, Octave };
inline bool nested(ShowStyle s) { return s == ShowStyle::Python; }
