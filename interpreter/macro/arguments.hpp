// G65/G66 arguments: which local variable a macro argument's letter sets ([FANUC] custom macro,
// "Argument specification"; dialects.md §3.7). The interpreter assigns the arguments with it and
// the analyzer reads a macro's documented or passed arguments with it (K4001).
#pragma once

namespace kerf::interpreter::macro {

// Argument specification I: address → local variable (dialects.md §3.7; [FANUC] custom macro).
inline int specification_one(char letter) {
    switch (letter) {
        case 'A': return 1;  case 'B': return 2;  case 'C': return 3;  case 'I': return 4;
        case 'J': return 5;  case 'K': return 6;  case 'D': return 7;  case 'E': return 8;
        case 'F': return 9;  case 'H': return 11; case 'M': return 13; case 'Q': return 17;
        case 'R': return 18; case 'S': return 19; case 'T': return 20; case 'U': return 21;
        case 'V': return 22; case 'W': return 23; case 'X': return 24; case 'Y': return 25;
        case 'Z': return 26; default: return 0;
    }
}

// Specification II: A B C, then up to ten sets I J K → #4..#33 (I_n = #(3n+1), J_n = #(3n+2),
// K_n = #(3n+3)). A set ends when a letter does not come later in I J K than the previous one,
// so `I1 K3 I4` is I1 K1 I2. The first set is specification I's I J K (#4 #5 #6), so one
// mapping serves both, and where both name one variable the later word wins ([FANUC]).
class ArgumentMapper {
public:
    int variable(char letter) {
        const int ijk = letter == 'I' ? 0 : letter == 'J' ? 1 : letter == 'K' ? 2 : -1;
        if (ijk < 0) return specification_one(letter);
        if (ijk <= last_ijk_) ++set_;
        last_ijk_ = ijk;
        return set_ < 10 ? 4 + 3 * set_ + ijk : 0;   // an 11th set has no variable
    }

private:
    int set_ = 0;
    int last_ijk_ = -1;
};


}  // namespace kerf::interpreter::macro
