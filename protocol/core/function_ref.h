#pragma once
// A reference to a callable without allocation: one indirect call. Used on the hot path (framer
// → sentence callback, decoder → message) where std::function would cost an allocation check per
// call.
//
// A named callable (an lvalue) is referred to and must outlive the FunctionRef. A temporary (a
// lambda written in the call, a function pointer) is copied into the FunctionRef itself, so a
// FunctionRef built from a temporary stays valid wherever it is kept: the dangling reference a
// temporary lambda used to leave in a stored FunctionRef (DecodeContext) cannot happen. Such a
// temporary must be small and trivially copyable (captures by reference are); anything else is
// refused at compile time.
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace gnss {

template <class Signature> class FunctionRef;

template <class R, class... Args> class FunctionRef<R(Args...)> {
public:
    static constexpr std::size_t kInlineBytes = 8 * sizeof(void *);

    template <class F, class = std::enable_if_t<!std::is_same_v<std::decay_t<F>, FunctionRef> &&
                                                std::is_invocable_r_v<R, F &, Args...>>>
    FunctionRef(F &&f) noexcept { // NOLINT(google-explicit-constructor): by design
        using T = std::remove_reference_t<F>;
        if constexpr (std::is_lvalue_reference_v<F>) {
            object_ = const_cast<void *>(static_cast<const void *>(std::addressof(f)));
            call_ = [](const FunctionRef &self, Args... args) -> R {
                return (*static_cast<T *>(self.object_))(std::forward<Args>(args)...);
            };
        } else {
            static_assert(sizeof(T) <= kInlineBytes && alignof(T) <= alignof(std::max_align_t),
                          "a temporary callable kept by FunctionRef must be small: name it "
                          "(an lvalue is referred to, not copied)");
            static_assert(std::is_trivially_copyable_v<T>,
                          "a temporary callable kept by FunctionRef must be trivially copyable "
                          "(capture by reference), or be named (an lvalue is referred to)");
            ::new (static_cast<void *>(storage_)) T(std::move(f));
            call_ = [](const FunctionRef &self, Args... args) -> R {
                const void *p = self.storage_;
                return (*std::launder(static_cast<T *>(const_cast<void *>(p))))(
                        std::forward<Args>(args)...);
            };
        }
    }

    R operator()(Args... args) const { return call_(*this, std::forward<Args>(args)...); }

private:
    void *object_ = nullptr;
    R (*call_)(const FunctionRef &, Args...);
    alignas(std::max_align_t) unsigned char storage_[kInlineBytes];
};

} // namespace gnss
