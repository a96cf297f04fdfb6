// m3g-vk's C++ exceptions as the Java exceptions JSR-184 1.1 names: the
// class of the same name in java.lang (java.io.IOException for the Loader),
// the C++ message kept.
#include <exception>
#include <new>

#include <m3g/Exception.h>

#include "Jni.h"

namespace m3gjni {

void throwJava(JNIEnv* env, const char* cls, const std::string& message) {
    if (env->ExceptionCheck()) return;  // the first one stands
    jclass c = env->FindClass(cls);
    if (c) env->ThrowNew(c, message.c_str());
}

void rethrowAsJava(JNIEnv* env) noexcept {
    try {
        throw;
    } catch (const JavaExceptionPending&) {
        // Already thrown in Java.
    } catch (const m3g::NullPointerException& e) {
        throwJava(env, "java/lang/NullPointerException", e.what());
    } catch (const m3g::IllegalArgumentException& e) {
        throwJava(env, "java/lang/IllegalArgumentException", e.what());
    } catch (const m3g::IndexOutOfBoundsException& e) {
        throwJava(env, "java/lang/IndexOutOfBoundsException", e.what());
    } catch (const m3g::ArithmeticException& e) {
        throwJava(env, "java/lang/ArithmeticException", e.what());
    } catch (const m3g::IOException& e) {
        throwJava(env, "java/io/IOException", e.what());
    } catch (const m3g::IllegalStateException& e) {  // m3g::vk::VulkanError too
        throwJava(env, "java/lang/IllegalStateException", e.what());
    } catch (const m3g::OutOfMemoryError& e) {
        throwJava(env, "java/lang/OutOfMemoryError", e.what());
    } catch (const std::bad_alloc&) {
        throwJava(env, "java/lang/OutOfMemoryError", "m3g-vk: out of native memory");
    } catch (const std::exception& e) {
        throwJava(env, "java/lang/RuntimeException", e.what());
    } catch (...) {
        throwJava(env, "java/lang/RuntimeException", "m3g-vk: unknown native error");
    }
}

}  // namespace m3gjni
