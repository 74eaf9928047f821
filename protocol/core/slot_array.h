#pragma once
// SlotArray<T, N>: room for N values of a trivially copyable T, of which a message uses the first
// few, counted beside it (a GSV's satellites, a GSA's ids). Unlike std::array<T, N>{} it is not
// cleared when made: the hot decoders make a message for every sentence, and clearing the 16
// satellites of a GSV that fills four (`rep stos`) was a quarter of its decode, the GSA's 32 ids
// and satellites a quarter of its. Only slots below the count are read, and each is assigned
// whole before its members are.
#include <cstddef>
#include <type_traits>

namespace gnss {

template <class T, std::size_t N> class SlotArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "SlotArray holds plain values");

public:
    SlotArray() {} // leaves the slots unwritten (a union member is not made by default)
    static constexpr std::size_t size() { return N; }
    T &operator[](std::size_t i) { return slots_[i]; }
    const T &operator[](std::size_t i) const { return slots_[i]; }

private:
    union {
        T slots_[N];
    };
};

} // namespace gnss
